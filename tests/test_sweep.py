"""Parallel sweeps equal the serial ones: joblib processes and a Dask LocalCluster on loopback."""

import numpy as np
import pytest

from obslib.studies import general_assignment
from obslib.studies import greedy_vs_relaxed as gvr
from obslib.sweep import run_sweep


def test_joblib_equals_serial():
    a = gvr.fig8_sweep([1, 3, 5], trials=3, seed=2)
    b = gvr.fig8_sweep([1, 3, 5], trials=3, seed=2, backend="joblib", n_jobs=2)
    for k in ("greedy", "relaxed", "relaxed_ordered"):
        np.testing.assert_array_equal(a[k], b[k])
    np.testing.assert_array_equal(
        general_assignment.fig9_sweep([20, 23], 3, 1),
        general_assignment.fig9_sweep([20, 23], 3, 1, backend="joblib", n_jobs=2),
    )


def test_dask_local_cluster_equals_serial():
    distributed = pytest.importorskip("distributed")
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, host="127.0.0.1",
                                  dashboard_address=None, processes=True) as cluster:
        address = cluster.scheduler_address
        assert address.startswith("tcp://127.0.0.1:")
        a = gvr.fig8_sweep([2, 4], trials=3, seed=7)
        b = gvr.fig8_sweep([2, 4], trials=3, seed=7, backend="dask", scheduler=address)
        for k in ("greedy", "relaxed", "relaxed_ordered"):
            np.testing.assert_array_equal(a[k], b[k])
        np.testing.assert_array_equal(
            general_assignment.fig9_sweep([20], 4, 3),
            general_assignment.fig9_sweep([20], 4, 3, backend="dask", scheduler=address),
        )


def test_bad_backend():
    with pytest.raises(ValueError, match="backend"):
        run_sweep(abs, [{"x": 1}], backend="mpi")
    with pytest.raises(ValueError, match="scheduler"):
        run_sweep(abs, [{"x": 1}], backend="dask")


def test_progress_bar_goes_to_stderr_and_leaves_the_results(capfd):
    tasks = [dict(base=2, exp=k) for k in range(5)]
    assert run_sweep(pow, tasks, progress=True) == run_sweep(pow, tasks) == [1, 2, 4, 8, 16]
    out, err = capfd.readouterr()
    assert out == "" and "5/5" in err
    assert run_sweep(pow, tasks, backend="joblib", n_jobs=2, progress=True) == [1, 2, 4, 8, 16]
    assert "5/5" in capfd.readouterr().err
    with pytest.raises(ValueError, match="progress"):
        run_sweep(pow, tasks, progress="yes")
