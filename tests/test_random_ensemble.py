"""Random-vibration ensembles on the map engine (symimpact.maps.ensemble): the same seed gives the
same rows on every executor and worker count, the statistics are those of the in-process
ensemble, and an interrupted ensemble resumes from its file computing only what is missing."""

import numpy as np
import pandas as pd
import pytest

from symimpact.errors import ParameterError
from symimpact.forced.loads.random_response import random_statistics
from symimpact.maps.ensemble import random_ensemble
from symimpact.model.system import ImpactSystem

SYSTEM = ImpactSystem(M=1.0, K=1000.0, C=0.5, m=0.05, gap=0.01, contact="linear", k1=1e6)
ARGS = (SYSTEM, 0.02, (0.2, 50.0), 20.0, 0.002)
KW = {"e": 0.6, "realisations": 10, "seed": 4, "settle": 5.0}


@pytest.fixture(scope="module")
def serial():
    return random_ensemble(*ARGS, executor="serial", **KW)


def test_the_ensemble_is_the_in_process_statistics(serial):
    st, table = serial
    direct = random_statistics(*ARGS, **KW)
    for key in ("displacement", "velocity", "acceleration", "base_force"):
        assert np.array_equal(st.per_realisation[key], direct.per_realisation[key])
        assert st.rms_ci95[key] == direct.rms_ci95[key]
        assert st.reduction[key] == direct.reduction[key]
    assert list(table["run"]) == list(range(10))
    assert table["impacts"].sum() > 0


def test_processes_and_dask_give_the_same_rows(serial):
    distributed = pytest.importorskip("distributed")
    _, table = serial
    for workers in (1, 2):
        _, procs = random_ensemble(*ARGS, executor="processes", workers=workers, **KW)
        pd.testing.assert_frame_equal(procs, table, check_exact=True)
    with (
        distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                 dashboard_address=None) as cluster,
        distributed.Client(cluster) as client,
    ):  # fmt: skip
        _, dask = random_ensemble(*ARGS, client=client, **KW)
    pd.testing.assert_frame_equal(dask, table, check_exact=True)


class _Stop(Exception):
    pass


@pytest.mark.parametrize("suffix", [".csv", ".parquet"])
def test_an_interrupted_ensemble_resumes(tmp_path, serial, suffix):
    out = tmp_path / f"ensemble{suffix}"
    seen = []

    def stop(done, total):
        seen.append(done)
        if done >= 4:
            raise _Stop

    with pytest.raises(_Stop):
        random_ensemble(*ARGS, executor="serial", out=out, progress=stop, **KW)
    resumed = []
    _, table = random_ensemble(*ARGS, executor="serial", out=out,
                               progress=lambda d, t: resumed.append(d), **KW)  # fmt: skip
    assert resumed[0] >= 5  # the realisations already in the file are not run again
    pd.testing.assert_frame_equal(table, serial[1], check_exact=True)


def test_bad_ensembles_are_refused():
    with pytest.raises(ParameterError, match="realisations"):
        random_ensemble(*ARGS, e=0.6, realisations=0)
    with pytest.raises(ParameterError, match="psd"):
        random_ensemble(SYSTEM, ((1.0, 0.5), (1.0, 1.0)), (0.2, 50.0), 20.0, 0.002, e=0.6,
                        realisations=2)  # fmt: skip
