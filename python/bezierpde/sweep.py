"""Parameter sweeps from Python: the same expanded jobs and rows as ``bpde sweep``.

The expansion of a spec into jobs is the C++ one (jobs/sweep.h, ``bezierpde.expand_sweep``), and
every job runs through the same C++ function as the command's thread pool
(``run_sweep_job``), so a row here equals the command's row (but for ``seconds``).
"""

import os
import tempfile

from . import _core


def _run_job(job, directory, resume):
    # Module-level so that Dask and process pools pickle it by reference.
    return _core.run_sweep_job(job, directory, resume)


def _table(rows, columns):
    try:
        import pandas
    except ImportError:
        return [{c: row.get(c) for c in columns} for row in rows]
    return pandas.DataFrame([{c: row.get(c) for c in columns} for row in rows], columns=columns)


def sweep(spec, client=None, out=None, jobs=None, resume=True, base_dir=None):
    """Run a sweep (FORMATS.md "Sweeps") and return its table, one row per job.

    spec     a SWEEP dict, or the path of a SWEEP.json file (its "base" file relative to it).
    client   a ``dask.distributed.Client``: the jobs run on its workers (each job's folder is
             written by the worker that runs it, so ``out`` must be a folder they all see);
             None: local processes (``jobs`` of them: 1..1024 as ``bpde sweep --jobs``; None or 0:
             one per core).
    out      the output folder (jobs/<id>/ per job, results.csv, results.jsonl), as
             ``bpde sweep --out``; default a new temporary folder. Jobs already done there are
             skipped when ``resume``.
    Returns a pandas DataFrame with the columns of results.csv when pandas is installed, else a
    list of row dicts. Bad specs raise ``bezierpde.InvalidInput`` (a spec file is read as ``bpde
    sweep`` reads it: a key given twice is a ``ParseError``); failed jobs are rows.
    """
    if jobs is not None:
        if isinstance(jobs, bool) or not isinstance(jobs, int):
            raise _core.ParameterError(f"jobs: expected an int, got {type(jobs).__name__}")
        if not 0 <= jobs <= _core.MAX_SWEEP_THREADS:
            raise _core.ParameterError(f"jobs: expected 0..{_core.MAX_SWEEP_THREADS} (0: one per core), got {jobs}")
    if isinstance(spec, (str, os.PathLike)):
        path = os.fspath(spec)
        spec = _core.read_json_file(path)
        if base_dir is None:
            base_dir = os.path.dirname(path) or "."
    if base_dir is None:
        base_dir = "."
    expanded, columns = _core.expand_sweep(spec, base_dir)
    out_dir = os.path.abspath(out) if out is not None else tempfile.mkdtemp(prefix="bezierpde-sweep-")
    dirs = [os.path.join(out_dir, "jobs", job["id"]) for job in expanded]
    if client is not None:
        futures = client.map(_run_job, expanded, dirs, [resume] * len(expanded), pure=False)
        rows = client.gather(futures)
    elif expanded:
        from concurrent.futures import ProcessPoolExecutor

        with ProcessPoolExecutor(max_workers=jobs or os.cpu_count()) as pool:
            rows = list(pool.map(_run_job, expanded, dirs, [resume] * len(expanded)))
    else:
        rows = []
    _core.write_sweep_tables(spec, base_dir, out_dir, rows)
    return _table(rows, columns)
