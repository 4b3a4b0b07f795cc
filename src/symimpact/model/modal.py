"""A structure's modes at the damper's point from a finite-element model: the stiffness and mass
matrices K and M of the constrained model, read from ``.npz`` (arrays ``K`` and ``M``), Matrix
Market ``.mtx``, ``.npy`` or CSV files, reduced to their first N modes at an attachment degree of
freedom (issue 36, a primary given by its finite-element model).

Each mode i is normalised to unit modal mass, φᵢᵀMφᵢ = 1; referred to the attachment DOF j (the
displacement there is the mode's coordinate) its mass is Mᵢ = 1/φᵢⱼ² and its stiffness
Kᵢ = ωᵢ²Mᵢ — the same reduction as Step 1 and Step 14 apply to a beam's modes (Eq. 5–6, F6), so
that one mode is the primary a damper at that DOF sees.  The DOF's static flexibility
(K⁻¹)ⱼⱼ is the limit of Σᵢ 1/Kᵢ over all modes: how much of it the first N carry says whether
they describe the point.

Given the influence vector r (each DOF's displacement when the supports move by one unit: 1 for
the translations along the motion, 0 for rotations), each mode also gets its participation
factor referred to the DOF, Γᵢ = φᵢⱼ·φᵢᵀMr (the supports' motion x_b drives it as a base
motion Γᵢx_b, Step 15, Eq. F7), and the share of the model's mass rᵀMr it moves,
(φᵢᵀMr)²/rᵀMr (its effective modal mass; over all modes the shares sum to 1).  M is the
constrained model's: mass that a consistent mass matrix couples to the supports themselves
(their rows and columns, removed with them) is not in the load, an error of the order of one
element's share of the mass (lumped masses have none).

The eigenproblem is solved in its flexibility form, M v = μ K v with μ = 1/ω² (a Cholesky
factor of K), so that the lowest modes keep their relative accuracy whatever the model's
highest frequency; a sparse model (``.mtx``, or ``.npz`` of scipy sparse matrices) is solved by
ARPACK in shift-invert mode about zero.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from ..errors import ParameterError

#: Below this many degrees of freedom a sparse model is solved densely.
DENSE = 2000


@dataclass(frozen=True)
class FEMode:
    """One mode of a finite-element model referred to its attachment DOF (SI)."""

    number: int
    #: natural angular frequency [rad/s]
    omega: float
    #: modal mass referred to the DOF, 1/φⱼ² for φ of unit modal mass [kg] (inf at a node)
    M: float
    #: modal stiffness referred to the DOF, ω²M [N/m] (inf at a node)
    K: float
    #: the unit-modal-mass shape at the DOF [kg^-1/2]
    shape: float
    #: participation factor referred to the DOF, Γ = φⱼ·φᵀMr (Eq. F7) [1]; None without r
    participation: float | None = None
    #: share of the mass rᵀMr the mode moves under base excitation, (φᵀMr)²/rᵀMr [1]
    mass_share: float | None = None

    @property
    def frequency(self) -> float:
        """Natural frequency ω/2π [Hz]."""
        return self.omega / (2.0 * math.pi)

    @property
    def node(self) -> bool:
        """True when the mode does not move the DOF."""
        return not math.isfinite(self.M)

    def as_dict(self) -> dict[str, Any]:
        return {"mode": self.number, "omega": self.omega, "frequency": self.frequency,
                "M": None if self.node else self.M, "K": None if self.node else self.K,
                "shape": self.shape, "node": self.node, "participation": self.participation,
                "mass_share": self.mass_share}  # fmt: skip


def _read_one(name: str, path: Path):
    """One matrix from ``path`` (.mtx, .npy or .csv)."""
    from ..io import input_file

    suffix = path.suffix.lower()
    input_file(path, name)
    try:
        if suffix == ".mtx":
            from scipy.io import mmread

            return mmread(str(path))
        if suffix == ".npy":
            return np.load(path, allow_pickle=False)
        if suffix == ".csv":
            return np.loadtxt(path, delimiter=",", ndmin=2)
    except FileNotFoundError:
        raise ParameterError(name, f"no file {path}") from None
    except (OSError, ValueError) as exc:
        raise ParameterError(name, f"{path} is not a readable matrix ({exc})") from None
    raise ParameterError(name, f"{path}: give a .mtx, .npy or .csv file (or one .npz of K and M)")


def read_matrices(fe: Any = None, K: Any = None, M: Any = None) -> tuple[Any, Any]:
    """(K [N/m], M [kg]) of a finite-element model: from one ``.npz`` file ``fe`` holding arrays
    ``K`` and ``M`` (dense, or scipy sparse saved by ``scipy.sparse.save_npz`` as ``K.npz`` and
    ``M.npz`` given as ``K`` and ``M``), or from two files ``K`` and ``M`` (.mtx, .npy, .csv)."""
    if fe is not None:
        if K is not None or M is not None:
            raise ParameterError("fe", "give either one .npz file of K and M or the two files")
        from ..io import input_file

        path = Path(fe)
        if path.suffix.lower() != ".npz":
            raise ParameterError("fe", f"{path}: an .npz file holding arrays K and M")
        input_file(path, "fe")
        try:
            with np.load(path, allow_pickle=False) as data:
                if "K" not in data or "M" not in data:
                    raise ParameterError("fe", f"{path} holds {sorted(data)}, not arrays K and M")
                return data["K"], data["M"]
        except FileNotFoundError:
            raise ParameterError("fe", f"no file {path}") from None
        except (OSError, ValueError) as exc:
            raise ParameterError("fe", f"{path} is not a readable .npz file ({exc})") from None
    if K is None or M is None:
        raise ParameterError("K" if K is None else "M", "needs both matrices (or one .npz)")
    out = []
    for name, value in (("K", K), ("M", M)):
        path = Path(value)
        if path.suffix.lower() == ".npz":
            from scipy import sparse

            try:
                out.append(sparse.load_npz(path))
            except (OSError, ValueError) as exc:
                raise ParameterError(name, f"{path} is not a scipy sparse .npz ({exc})") from None
        else:
            out.append(_read_one(name, path))
    return out[0], out[1]


def _checked(name: str, A: Any, n: int | None):
    from scipy import sparse

    if sparse.issparse(A):
        A = sparse.csc_matrix(A, dtype=float)
        data = A.data
    else:
        A = np.asarray(A, dtype=float)
        data = A
    if A.ndim != 2 or A.shape[0] != A.shape[1]:
        raise ParameterError(name, f"must be a square matrix, got shape {A.shape}")
    if n is not None and A.shape[0] != n:
        raise ParameterError(name, f"is {A.shape[0]}×{A.shape[0]}, K is {n}×{n}")
    if not np.all(np.isfinite(data)):
        raise ParameterError(name, "holds a value that is not a finite number")
    asym = abs(A - A.T).max() if sparse.issparse(A) else np.max(np.abs(A - A.T))
    if asym > 1e-10 * max(abs(A).max(), 1e-300):
        raise ParameterError(name, f"is not symmetric (largest |A − Aᵀ| {asym:.3g})")
    return A


#: Largest condition number (largest over smallest eigenvalue) of a mass or stiffness matrix:
#: beyond it the smallest eigenvalue is rounding (1e13 leaves 3 of a double's 16 digits).
MAX_CONDITION = 1e13


def _definite(name: str, A: Any, remedy: str) -> None:
    """Refuse a symmetric matrix that is not positive definite, or whose condition number
    (largest over smallest eigenvalue) exceeds :data:`MAX_CONDITION`, stating the condition."""
    from scipy import sparse
    from scipy.linalg import eigvalsh

    Ad = A.toarray() if sparse.issparse(A) else np.asarray(A)
    if Ad.size == 0:
        raise ParameterError(name, "is an empty matrix")
    lam = eigvalsh(Ad)
    low, high = float(lam[0]), float(lam[-1])
    if high <= 0 or low <= 0 or high / low > MAX_CONDITION:
        cond = "infinite" if low <= 0 else f"{high / low:.3g}"
        raise ParameterError(
            name,
            f"the model is not positive definite ({name}'s eigenvalues run from {low:.3g} to "
            f"{high:.3g}, condition {cond}; at most {MAX_CONDITION:g} is read): {remedy}",
        )


def influence_vector(pattern: Any, size: int) -> np.ndarray:
    """The influence vector r of a model of ``size`` DOFs from ``pattern``: a sequence (or a
    comma-separated text) of numbers repeated to fill the DOFs ("1" for a model of
    translations, "1,0" for a beam's (w, θ) pairs)."""
    if isinstance(pattern, str):
        try:
            values = [float(v) for v in pattern.split(",")]
        except ValueError:
            raise ParameterError(
                "influence", f"numbers separated by commas, got {pattern!r}"
            ) from None
    else:
        values = [float(v) for v in np.ravel(np.asarray(pattern, dtype=float))]
    if not values or size % len(values) or not all(math.isfinite(v) for v in values):
        raise ParameterError(
            "influence", f"{len(values)} finite values do not repeat to fill {size} DOFs"
        )
    r = np.tile(np.array(values), size // len(values))
    if not np.any(r):
        raise ParameterError("influence", "is zero everywhere: no DOF moves with the supports")
    return r


def unit_modes(K: Any, M: Any, n: int) -> tuple[np.ndarray, np.ndarray]:
    """(ω², modes as columns of unit modal mass φᵀMφ = 1) of the ``n`` lowest modes of K, M
    (checked by :func:`_checked`): the flexibility form M v = μ K v (dense) or ARPACK in
    shift-invert mode about zero (sparse, above DENSE DOFs)."""
    from scipy import sparse
    from scipy.linalg import LinAlgError, eigh

    size = K.shape[0]
    if not (sparse.issparse(K) and size > DENSE):
        _definite("M", M, "a DOF without mass: condense it out of the model (static condensation)")
        _definite("K", K, "a rigid-body mode: constrain the model at its supports")
    try:
        if sparse.issparse(K) and size > DENSE:
            from scipy.sparse.linalg import eigsh

            lam, vec = eigsh(K, k=n, M=sparse.csc_matrix(M), sigma=0.0, which="LM")
            order = np.argsort(lam)
            lam, vec = lam[order], vec[:, order]
        else:
            Kd = K.toarray() if sparse.issparse(K) else K
            Md = M.toarray() if sparse.issparse(M) else M
            mu, vec = eigh(Md, Kd, subset_by_index=[size - n, size - 1])
            lam, vec = 1.0 / mu[::-1], vec[:, ::-1]
    except (LinAlgError, RuntimeError, ValueError) as exc:
        raise ParameterError(
            "K",
            "the model is not positive definite (a rigid-body mode, or M singular): constrain "
            f"it at its supports ({exc})",
        ) from None
    if not np.all(lam > 0):
        raise ParameterError("K", "the model has a mode of zero or negative stiffness")
    if not np.all(np.isfinite(lam)):  # M singular: a mode of infinite frequency
        raise ParameterError("M", "is singular (a mode of infinite frequency): a DOF without "
                             "mass; condense it out of the model")  # fmt: skip
    Mv = M @ vec
    vec = vec / np.sqrt(np.einsum("ij,ij->j", vec, Mv))  # unit modal mass
    return lam, vec


def fe_modes(K: Any, M: Any, dof: Any, n: Any = 1, influence: Any = None) -> list[FEMode]:
    """The first ``n`` modes of the model (K [N/m], M [kg], constrained: K positive definite)
    referred to DOF ``dof`` (0-based): ω from K v = ω²M v, Mᵢ = 1/φᵢⱼ² with φᵢ of unit modal
    mass, Kᵢ = ωᵢ²Mᵢ (the reduction of Eq. 5–6 and F6 applied to the model's modes); with the
    ``influence`` vector r (:func:`influence_vector`), Γᵢ = φᵢⱼ·φᵢᵀMr and the share
    (φᵢᵀMr)²/rᵀMr (Eq. F7)."""

    K = _checked("K", K, None)
    size = K.shape[0]
    M = _checked("M", M, size)
    if not isinstance(dof, int | np.integer) or isinstance(dof, bool) or not 0 <= dof < size:
        raise ParameterError("dof", f"a degree of freedom from 0 to {size - 1}, got {dof!r}")
    if not isinstance(n, int | np.integer) or isinstance(n, bool) or not 1 <= n <= min(size, 100):
        raise ParameterError("modes", f"a whole number from 1 to {min(size, 100)}, got {n!r}")
    lam, vec = unit_modes(K, M, n)
    if influence is not None:
        r = influence_vector(influence, size)
        Mr = M @ r
        loads = vec.T @ Mr  # φᵢᵀMr
        total = float(r @ Mr)
    modes = []
    for i in range(n):
        phi = float(vec[dof, i])
        omega = float(math.sqrt(lam[i]))
        gamma = share = None
        if influence is not None:
            gamma, share = phi * float(loads[i]), float(loads[i]) ** 2 / total
        # a node: the DOF's share of the mode's largest displacement below 1e-9
        if abs(phi) < 1e-9 * float(np.max(np.abs(vec[:, i]))):
            modes.append(FEMode(i + 1, omega, math.inf, math.inf, phi, gamma, share))
        else:
            Mi = 1.0 / phi**2
            modes.append(FEMode(i + 1, omega, Mi, omega * omega * Mi, phi, gamma, share))
    return modes


def static_flexibility(K: Any, dof: Any) -> float:
    """(K⁻¹)ⱼⱼ [m/N]: the DOF's deflection under a unit static force there, the limit of Σ 1/Kᵢ
    over all the model's modes."""
    from scipy import sparse
    from scipy.linalg import LinAlgError, solve

    K = _checked("K", K, None)
    size = K.shape[0]
    if not isinstance(dof, int | np.integer) or isinstance(dof, bool) or not 0 <= dof < size:
        raise ParameterError("dof", f"a degree of freedom from 0 to {size - 1}, got {dof!r}")
    load = np.zeros(size)
    load[dof] = 1.0
    try:
        if sparse.issparse(K):
            from scipy.sparse.linalg import spsolve

            u = spsolve(K, load)
        else:
            u = solve(K, load, assume_a="pos")
    except LinAlgError:
        raise ParameterError("K", "is singular: constrain the model at its supports") from None
    return float(u[dof])
