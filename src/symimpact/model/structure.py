"""A primary of several modes with its named points: a beam's Ritz modes (Step 14), a modal
model, or a finite-element model reduced to its first modes (Step 15), in one description.

Each mode i has its natural angular frequency ωᵢ [rad/s], damping ratio ζᵢ, generalised mass Mᵢ
and its shape's values φᵢ(p) at the named points p, in the normalisation Mᵢ belongs to (any:
only φᵢ(p)φᵢ(q)/Mᵢ and Γᵢ·φᵢ(p) are physical).  The structure's displacement at p is
x(p) = Σ φᵢ(p)qᵢ, and each modal coordinate obeys Step 15's equation (Eq. F7)

    Mᵢ(q̈ᵢ + 2ζᵢωᵢq̇ᵢ + ωᵢ²qᵢ) = Σ_p φᵢ(p)·f(p) + Mᵢ(2ζᵢωᵢẋ_b + ωᵢ²x_b)·Γᵢ,

where Γᵢ = φᵢᵀMr/Mᵢ is the mode's participation factor when the supports move by x_b (r: each
degree of freedom's displacement for a unit support motion).  From these:

- the receptance between two points, H(p, q; Ω) = Σ φᵢ(p)φᵢ(q)/(Mᵢ(ωᵢ² − Ω² + 2iζᵢωᵢΩ))
  (:meth:`Structure.receptance`), and the absolute response at p to a support motion,
  1 + Σ φᵢ(p)Γᵢ·Ω²/(ωᵢ² − Ω² + 2iζᵢωᵢΩ) (:meth:`Structure.base_transmissibility`);
- the mass an impact at p meets, 1/m_eff(p) = Σ φᵢ(p)²/Mᵢ (Step 15, item 4: the impulse enters
  each mode through φᵢ(p)) (:meth:`Structure.effective_mass`).

The structure file (:func:`read_structure`, JSON or TOML) gives one of ``"beam"``, ``"modes"`` or
``"fe"``, and ``"points"`` naming where dampers, stops and forces attach.  Values are SI numbers
or quantity texts (``"20 mm"``).
"""

from __future__ import annotations

import math
import tomllib
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from ..errors import ParameterError
from .beams import MAX_MODES, SUPPORTS, _support
from .modal import _checked, influence_vector, static_flexibility, unit_modes
from .units import nonnegative_float, positive_float, si_float

#: Largest number of modes a structure keeps (the beams' kernels carry MAX_MODES roots; beyond a
#: few dozen modes the model's own discretisation, not the modal truncation, limits a result).
MAX_STRUCTURE_MODES = 100


@dataclass(frozen=True)
class StructureMode:
    """One mode of a structure (SI): ``omega`` ωᵢ [rad/s], ``zeta`` ζᵢ [1], ``mass`` the
    generalised mass Mᵢ of the shape as given, ``shape`` φᵢ at each named point, and
    ``participation`` Γᵢ = φᵢᵀMr/Mᵢ (Eq. F7; 0 when the supports do not drive the mode)."""

    number: int
    omega: float
    zeta: float
    mass: float
    shape: dict[str, float]
    participation: float = 0.0
    #: the largest value of the shape over the whole structure (a beam's span, a model's DOFs;
    #: for modal data, over its points): a point where the shape is below 1e-9 of it is a node
    largest: float = math.nan

    def node_at(self, point: str) -> bool:
        """True where the mode does not move ``point`` (its shape there below 1e-9 of its
        largest value)."""
        scale = self.largest if math.isfinite(self.largest) else max(map(abs, self.shape.values()))
        return abs(self.shape[point]) <= 1e-9 * scale

    @property
    def frequency(self) -> float:
        """Natural frequency ωᵢ/2π [Hz]."""
        return self.omega / (2.0 * math.pi)

    def as_dict(self) -> dict[str, Any]:
        return {"mode": self.number, "omega": self.omega, "frequency": self.frequency,
                "zeta": self.zeta, "mass": self.mass, "shape": dict(self.shape),
                "participation": self.participation}  # fmt: skip


@dataclass(frozen=True)
class Structure:
    """A primary of ``modes`` with its named ``points`` (see the module docstring)."""

    modes: tuple[StructureMode, ...]
    points: tuple[str, ...]
    #: where the model came from: "beam", "modes" or "fe"
    source: str
    #: each point's static flexibility over all the structure's modes [m/N], the limit of the
    #: modal sum (a beam's statics, Eq. F6; a model's (K⁻¹)ⱼⱼ); empty for modal data
    flexibility: dict[str, float] = field(default_factory=dict)

    def flexibility_share(self, p: Any) -> float:
        """The share of point ``p``'s static flexibility the kept modes hold,
        Σ φᵢ(p)²/(Mᵢωᵢ²) over the exact value: how well the truncation describes the point
        (the point receptance at Ω = 0); nan for modal data, which carry no exact value."""
        key = self._point(p)
        exact = self.flexibility.get(key)
        if not exact:
            return math.nan
        return sum(m.shape[key] ** 2 / (m.mass * m.omega**2) for m in self.modes) / exact

    def shapes(self, points: Any = None) -> np.ndarray:
        """Φ, shape (len(points), N): φᵢ(p) of every mode at ``points`` (default: all)."""
        names = self.points if points is None else tuple(self._point(p) for p in points)
        return np.array([[m.shape[p] for m in self.modes] for p in names])

    def _point(self, p: Any) -> str:
        key = str(p)
        if key not in self.points:
            raise ParameterError("at", f"no point {key!r} (the structure's points: "
                                       f"{', '.join(self.points)})")  # fmt: skip
        return key

    def effective_mass(self, p: Any) -> float:
        """The mass an impact at point ``p`` meets [kg]: 1/m_eff = Σ φᵢ(p)²/Mᵢ (Step 15, item 4;
        one mode with φ = 1 gives its M, Step 9).  inf where no mode moves the point."""
        key = self._point(p)
        inverse = sum(m.shape[key] ** 2 / m.mass for m in self.modes)
        return math.inf if inverse == 0.0 else 1.0 / inverse

    def receptance(self, p: Any, q: Any, Omega: Any) -> Any:
        """H(p, q; Ω) [m/N]: the complex displacement at ``p`` per unit harmonic force at ``q``,
        Σ φᵢ(p)φᵢ(q)/(Mᵢ(ωᵢ² − Ω² + 2iζᵢωᵢΩ)) (Eq. F7 in the frequency domain); ``Omega``
        [rad/s] broadcasts."""
        a, b = self._point(p), self._point(q)
        W = np.asarray(Omega, dtype=float)
        out = np.zeros(W.shape, dtype=complex)
        for m in self.modes:
            w = m.omega
            out += m.shape[a] * m.shape[b] / (m.mass * (w * w - W * W + 2j * m.zeta * w * W))
        return out[()] if out.ndim == 0 else out

    def base_transmissibility(self, p: Any, Omega: Any) -> Any:
        """The complex absolute displacement at ``p`` per unit harmonic support motion [1]:
        r(p) + Σ φᵢ(p)Γᵢ·Ω²/(ωᵢ² − Ω² + 2iζᵢωᵢΩ), r(p) = 1 (a point that moves with the
        supports).  Eq. F7 written on the displacement relative to the supports, whose modal
        load is the inertia −MᵢΓᵢẍ_b: with all modes kept it equals Eq. F7's absolute form
        (Σ φᵢΓᵢ = r), and truncated it keeps the static part of the left-out modes."""
        a = self._point(p)
        W = np.asarray(Omega, dtype=float)
        out = np.ones(W.shape, dtype=complex)
        for m in self.modes:
            w = m.omega
            out += m.shape[a] * m.participation * W * W / (w * w - W * W + 2j * m.zeta * w * W)
        return out[()] if out.ndim == 0 else out


def _count(n: Any, most: int) -> int:
    if not isinstance(n, int) or isinstance(n, bool) or not 1 <= n <= most:
        raise ParameterError("modes", f"a whole number from 1 to {most}, got {n!r}")
    return n


def _zetas(zeta: Any, n: int) -> list[float]:
    values = list(zeta) if isinstance(zeta, list | tuple) else [zeta] * n
    if len(values) != n:
        raise ParameterError("zeta", f"{len(values)} damping ratios for {n} modes")
    out = [nonnegative_float("zeta", z) for z in values]
    if any(z >= 1.0 for z in out):
        raise ParameterError("zeta", "each damping ratio must lie below 1 (an underdamped mode)")
    return out


def _names(points: Any) -> dict[str, Any]:
    if not isinstance(points, dict) or not points:
        raise ParameterError("points", 'a table of named points, e.g. {"tip": "1 m"}')
    return {str(k): v for k, v in points.items()}


def beam_structure(support: str, E: Any, I: Any, rho: Any, A: Any, L: Any, points: Any,
                   modes: Any = 3, zeta: Any = 0.0) -> Structure:  # fmt: skip
    """The first ``modes`` Ritz modes of the ``support`` beam (Young's modulus ``E`` [Pa],
    second moment ``I`` [m⁴], density ``rho`` [kg/m³], section ``A`` [m²], length ``L`` [m];
    Eq. 3–6 for the cantilever, Eq. F6 for the others) at the named ``points`` ({name: distance
    from the clamp or the left support [m]}), each with ratio ``zeta`` (one, or one per mode).
    Mᵢ = ρAL∫φᵢ²dξ and Γᵢ = ∫φᵢdξ/∫φᵢ²dξ (Eq. F7, from the kernels referred to a point)."""
    support = _support(support)
    E, I, rho, A, L = (positive_float(k, v) for k, v in
                       zip("E I rho A L".split(), (E, I, rho, A, L), strict=True))  # fmt: skip
    n = _count(modes, MAX_MODES)
    zetas = _zetas(zeta, n)
    where = {}
    for name, r in _names(points).items():
        x = nonnegative_float(f"points.{name}", r, "m")
        if x > L * (1 + 1e-12):
            raise ParameterError(f"points.{name}", f"{x:g} m lies beyond the beam length {L:g} m")
        where[name] = min(x / L, 1.0)
    k = SUPPORTS[support]
    scale = math.sqrt(E * I / (rho * A * L**4))
    grid = np.linspace(0.05, 0.95, 19)
    out = []
    for i, bl in enumerate(k.roots[:n], start=1):
        bl = float(bl)
        # ∫φ²dξ and ∫φdξ from the kernels referred to the point where the mode moves most
        values = [abs(float(k.shape(bl, x))) for x in grid]
        x_ref = float(grid[int(np.argmax(values))])
        phi_ref = float(k.shape(bl, x_ref))
        norm = float(k.mass(bl, x_ref)) * phi_ref**2  # ∫φ²dξ
        gamma = float(k.participation(bl, x_ref)) / phi_ref  # ∫φdξ/∫φ²dξ
        gamma = 0.0 if abs(gamma) < 1e-12 else gamma  # antisymmetric modes of symmetric beams
        shape = {p: float(k.shape(bl, x)) for p, x in where.items()}
        largest = max(abs(float(k.shape(bl, x))) for x in np.linspace(0.0, 1.0, 201))
        out.append(StructureMode(i, bl * bl * scale, zetas[i - 1], rho * A * L * norm, shape,
                                 gamma, largest))  # fmt: skip
    flex = {p: float(k.flexibility(x)) * L**3 / (E * I) for p, x in where.items()}
    return Structure(tuple(out), tuple(where), "beam", flex)


def modal_structure(modes: Any) -> Structure:
    """A structure from modal data: ``modes`` a list of ``{"f" [Hz] | "omega" [rad/s], "mass"
    [kg], "zeta", "shape": {point: value}, "participation" (optional, Γᵢ)}``; every mode names
    the same points."""
    if not isinstance(modes, list | tuple) or not modes:
        raise ParameterError("modes", "a list of modes, each {f, mass, zeta, shape}")
    if len(modes) > MAX_STRUCTURE_MODES:
        raise ParameterError("modes", f"at most {MAX_STRUCTURE_MODES} modes, got {len(modes)}")
    out, points = [], None
    for i, m in enumerate(modes, start=1):
        where = f"modes[{i - 1}]"
        if not isinstance(m, dict):
            raise ParameterError(where, "a table {f, mass, zeta, shape}")
        if ("f" in m) == ("omega" in m):
            raise ParameterError(where, "give its frequency as one of f [Hz] or omega [rad/s]")
        omega = (2 * math.pi * positive_float(f"{where}.f", m["f"], "Hz") if "f" in m
                 else positive_float(f"{where}.omega", m["omega"], "rad/s"))  # fmt: skip
        mass = positive_float(f"{where}.mass", m.get("mass", 1.0), "kg")
        zeta = _zetas(m.get("zeta", 0.0), 1)[0]
        shape = m.get("shape")
        if not isinstance(shape, dict) or not shape:
            raise ParameterError(f"{where}.shape", "a table {point: value} of the mode's shape")
        shape = {
            str(p): si_float(f"{where}.shape.{p}", v, "dimensionless") for p, v in shape.items()
        }
        if points is None:
            points = tuple(shape)
        elif set(shape) != set(points):
            raise ParameterError(f"{where}.shape", f"names the points {sorted(shape)}; the first "
                                                   f"mode names {sorted(points)}")  # fmt: skip
        gamma = si_float(f"{where}.participation", m.get("participation", 0.0), "dimensionless")
        out.append(StructureMode(i, omega, zeta, mass, shape, gamma))
    order = sorted(range(len(out)), key=lambda j: out[j].omega)
    modes_sorted = tuple(
        StructureMode(
            k + 1, out[j].omega, out[j].zeta, out[j].mass, out[j].shape, out[j].participation
        )
        for k, j in enumerate(order)
    )
    return Structure(modes_sorted, points, "modes")


def fe_structure(M: Any, K: Any, points: Any, modes: Any = None, zeta: Any = None, C: Any = None,
                 influence: Any = 1.0) -> Structure:  # fmt: skip
    """The first ``modes`` modes (default: all, at most :data:`MAX_STRUCTURE_MODES`) of the
    finite-element model M ẍ + C ẋ + K x = f (M [kg], K [N/m] symmetric, positive definite:
    constrained at its supports) at the named ``points`` ({name: DOF, 0-based}), unit modal
    mass.  Damping: ``zeta`` (one ratio, or one per mode) or ``C`` [N s/m], which must be
    proportional (ΦᵀCΦ diagonal to 1e-8 of its diagonal) and gives ζᵢ = φᵢᵀCφᵢ/(2ωᵢ).
    ``influence``: r, each DOF's displacement per unit support motion (a number, or a pattern,
    :func:`~symimpact.model.modal.influence_vector`)."""
    K = np.asarray(_dense(_checked("K", K, None)), dtype=float)
    size = K.shape[0]
    M = np.asarray(_dense(_checked("M", M, size)), dtype=float)
    n = size if modes is None else _count(modes, size)
    n = min(n, MAX_STRUCTURE_MODES)
    where = {}
    for name, dof in _names(points).items():
        if not isinstance(dof, int) or isinstance(dof, bool) or not 0 <= dof < size:
            raise ParameterError(f"points.{name}", f"a DOF from 0 to {size - 1}, got {dof!r}")
        where[name] = dof
    lam, vec = unit_modes(K, M, n)
    omegas = np.sqrt(lam)
    if (zeta is None) == (C is None):
        raise ParameterError("zeta", "give the damping as one of zeta (modal ratios) or C")
    if C is not None:
        C = np.asarray(_dense(_checked("C", C, size)), dtype=float)
        modal = vec.T @ C @ vec
        diag = np.diag(modal)
        off = np.abs(modal - np.diag(diag)).max() if n > 1 else 0.0
        if off > 1e-8 * max(np.abs(diag).max(), 1e-300):
            raise ParameterError(
                "C",
                "is not proportional: its modal matrix is not diagonal "
                f"(largest off-diagonal {off:.3g}); give zeta instead",
            )
        zetas = _zetas([float(c / (2 * w)) for c, w in zip(diag, omegas, strict=True)], n)
    else:
        zetas = _zetas(zeta, n)
    r = influence_vector(influence if not isinstance(influence, float | int) else [influence],
                         size)  # fmt: skip
    loads = vec.T @ (M @ r)
    out = []
    for i in range(n):
        shape = {p: float(vec[d, i]) for p, d in where.items()}
        largest = float(np.max(np.abs(vec[:, i])))
        out.append(StructureMode(i + 1, float(omegas[i]), zetas[i], 1.0, shape, float(loads[i]),
                                 largest))  # fmt: skip
    flex = {p: static_flexibility(K, d) for p, d in where.items()}
    return Structure(tuple(out), tuple(where), "fe", flex)


def _dense(A: Any) -> Any:
    from scipy import sparse

    return A.toarray() if sparse.issparse(A) else A


def _matrix(name: str, value: Any, base: Path) -> Any:
    """A matrix given inline (nested lists) or as a path (.npy, .csv, .mtx, or an .npz holding
    one array of that name) relative to the structure file."""
    if isinstance(value, list):
        try:
            return np.array(value, dtype=float)
        except ValueError:
            raise ParameterError(f"fe.{name}", "rows of numbers of equal length") from None
    if isinstance(value, str):
        from .modal import _read_one

        path = (base / value) if not Path(value).is_absolute() else Path(value)
        if path.suffix.lower() == ".npz":
            from ..io import input_file

            input_file(path, f"fe.{name}")
            try:
                with np.load(path, allow_pickle=False) as data:
                    if name not in data:
                        raise ParameterError(f"fe.{name}", f"{path} holds no array {name!r}")
                    return data[name]
            except (OSError, ValueError) as exc:
                raise ParameterError(f"fe.{name}", f"{path} is not readable ({exc})") from None
        return _read_one(f"fe.{name}", path)
    raise ParameterError(f"fe.{name}", "nested lists of numbers, or a path to a matrix file")


#: The fields of a structure file that are not the structure: what acts on it.
LOADS = ("dampers", "stops", "force", "base")


def section_properties(text: Any) -> tuple[float, float]:
    """(A [m²], I [m⁴]) of a solid section as a designer names it: ``"50 mm x 10 mm"`` a
    rectangle of width b by thickness h, h along the motion (A = bh, I = bh³/12), or
    ``"round 20 mm"`` a solid circle of diameter d (A = πd²/4, I = πd⁴/64)."""
    words = " ".join(str(text).replace("×", " x ").split())
    if words.lower().startswith("round "):
        d = positive_float("beam.section", words[6:], "m")
        return math.pi * d * d / 4.0, math.pi * d**4 / 64.0
    parts = [p.strip() for p in words.replace(" X ", " x ").split(" x ")]
    if len(parts) != 2:
        raise ParameterError(
            "beam.section", f"must be 'width x thickness' (thickness along the motion, e.g. "
            f"'50 mm x 10 mm') or 'round DIAMETER', got {text!r}"
        )  # fmt: skip
    b, h = (positive_float("beam.section", p, "m") for p in parts)
    return b * h, b * h**3 / 12.0


def _beam_spec(spec: dict) -> dict:
    """A beam's parameters with ``material`` read as its E and ρ
    (:func:`symimpact.model.materials.material`) and ``section`` as its A and I
    (:func:`section_properties`); either may not be given beside what it replaces."""
    out = dict(spec)
    for key, replaces in (("material", ("E", "rho")), ("section", ("A", "I"))):
        if key not in out:
            continue
        both = [k for k in replaces if k in out]
        if both:
            raise ParameterError(f"beam.{both[0]}", f"the {key} gives it: give {key} or "
                                 f"{' and '.join(replaces)}, not both")  # fmt: skip
        if key == "material":
            from .materials import material

            found = material(out.pop(key))
            out["E"], out["rho"] = found.E, found.rho
        else:
            out["A"], out["I"] = section_properties(out.pop(key))
    return out


def structure_from_dict(data: Any, base: Path | None = None) -> Structure:
    """The structure a parsed structure file describes (see :func:`read_structure`)."""
    base = Path.cwd() if base is None else base
    if not isinstance(data, dict):
        raise ParameterError("structure", "a table with one of beam, modes or fe")
    given = [k for k in ("beam", "modes", "fe") if k in data]
    if len(given) != 1:
        raise ParameterError("structure", "give exactly one of beam, modes or fe, got "
                                          f"{given or 'none'}")  # fmt: skip
    kind = given[0]
    later = [k for k in LOADS if k in data]
    if later:
        raise ParameterError(later[0], "a structure file's dampers and loads are read by "
                                       "read_model (symimpact.model.structure_model); here the "
                                       "damper and the load come from the command's options")  # fmt: skip
    unknown = sorted(set(data) - {"beam", "modes", "fe", "points"})
    if unknown:
        raise ParameterError(unknown[0], "is not a field of a structure file (beam, modes or fe, "
                                         "and points)")  # fmt: skip
    if kind == "modes":
        if "points" in data:
            raise ParameterError("points", "modal data name their points in each mode's shape")
        return modal_structure(data["modes"])
    spec = data[kind]
    if not isinstance(spec, dict):
        raise ParameterError(kind, "a table of its parameters")
    points = data.get("points", spec.get("points"))
    if points is None and kind == "fe":
        size = len(spec["M"]) if isinstance(spec.get("M"), list) else None
        points = {str(d): d for d in range(size)} if size else None
    if kind == "beam":
        known = {"type", "E", "I", "rho", "A", "L", "modes", "zeta", "points", "material",
                 "section"}  # fmt: skip
        unknown = sorted(set(spec) - known)
        if unknown:
            raise ParameterError(f"beam.{unknown[0]}", f"is not a beam parameter ({sorted(known)})")
        spec = _beam_spec(spec)
        missing = [k for k in ("type", "E", "I", "rho", "A", "L") if k not in spec]
        if missing:
            raise ParameterError(f"beam.{missing[0]}", "is missing (or give " + {
                "E": "its material", "rho": "its material", "I": "its section",
                "A": "its section"}.get(missing[0], "it") + ")")  # fmt: skip
        return beam_structure(spec["type"], spec["E"], spec["I"], spec["rho"], spec["A"],
                              spec["L"], points, spec.get("modes", 3),
                              spec.get("zeta", 0.0))  # fmt: skip
    known = {"M", "K", "C", "zeta", "modes", "influence", "points"}
    unknown = sorted(set(spec) - known)
    if unknown:
        raise ParameterError(f"fe.{unknown[0]}", f"is not a model parameter ({sorted(known)})")
    for k in ("M", "K"):
        if k not in spec:
            raise ParameterError(f"fe.{k}", "is missing")
    C = _matrix("C", spec["C"], base) if "C" in spec else None
    return fe_structure(_matrix("M", spec["M"], base), _matrix("K", spec["K"], base), points,
                        spec.get("modes"), spec.get("zeta"), C,
                        spec.get("influence", 1.0))  # fmt: skip


def parsed_file(path: Any) -> tuple[Any, Path]:
    """A structure file's parsed content (JSON, or TOML by its suffix) and its folder.  A key
    given twice is refused (JSON as TOML does), and so are paths that are not a regular file of
    at most :data:`~symimpact.io.MAX_INPUT_BYTES` of UTF-8 text (:func:`~symimpact.io.input_text`)."""
    from ..io import input_text, strict_json

    text = input_text(path, "structure")
    p = Path(path)
    if p.suffix.lower() != ".toml":
        return strict_json(text, "structure", f"{p} "), p.parent
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise ParameterError("structure", f"{p} is not valid TOML ({exc})") from None
    except RecursionError:
        raise ParameterError(
            "structure", f"{p} nests arrays or tables too deeply to read"
        ) from None
    return data, p.parent


def read_structure(path: Any) -> Structure:
    """The structure in a JSON or TOML file: one of ``"beam"`` ({type, E, I, rho, A, L, modes,
    zeta}), ``"modes"`` (a list of {f, mass, zeta, shape: {point: value}}) or ``"fe"`` ({M, K,
    C or zeta, modes, influence}: matrices as nested lists or paths), and ``"points"`` ({name:
    distance along the beam, or DOF}; a model given inline names each DOF by its number when
    they are left out); values SI numbers or quantity texts.  The file's dampers and loads
    (``"dampers"``, ``"stops"``, ``"force"``, ``"base"``) are left to
    :func:`symimpact.model.structure_model.read_model`; here they are refused."""
    data, base = parsed_file(path)
    return structure_from_dict(data, base)
