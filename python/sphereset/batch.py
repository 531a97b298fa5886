"""Fit a whole collection of meshes on a Dask cluster, as ``sphereset batch`` does on one machine.

    python3 -m sphereset.batch INPUT -o OUT_DIR --scheduler tcp://HOST:8786 [fit options]
    python3 -m sphereset.batch INPUT -o OUT_DIR --local-workers 2 [fit options]

INPUT is a folder (every mesh file below it) or a manifest (.csv / .jsonl), as for
``sphereset batch``. Each mesh is one dask.distributed task that runs the library's batch core
(batch.hpp: processBatchItem) in a worker, so the sphere files, their records and
OUT_DIR/report.jsonl (one line per item, in item order, replaced when the run ends; the lines
of the run in progress are in report.jsonl.partial) are those the command line writes, and the
folder is locked for the run as the command line locks it; items already up to date are skipped (resume; --force fits
them again). Exit codes are those of `sphereset batch` (8: some items failed, 7: some failed
the coverage check).

On a real cluster the workers need the ``sphereset`` package installed (the same version) and
must see the input meshes and OUT_DIR at the same paths as this process: give absolute paths on
a shared file system (NFS, a mounted object store). The mesh paths of the items are passed to
the workers as listed (a relative INPUT gives relative paths, as in `sphereset batch`'s
report), so each worker resolves them against its own working directory: start the workers in
the same folder, or give INPUT as an absolute path. OUT_DIR is made absolute here.
"""

from __future__ import annotations

import argparse
import os
import sys
import time
import uuid
from typing import Any, Dict, List, Optional

from ._common import _repair_args, _repair_keyword_values, _repair_keywords
from . import _sphereset as _core

__all__ = ["batch_options", "list_items", "process_item", "run_batch", "main"]


# How long the command waits for a --scheduler to answer.
_SCHEDULER_TIMEOUT = "5s"

@_repair_keywords
def batch_options(n: Optional[int] = None, *, quality: str = "default", seed: int = 1, padding: float = 0.0,
                  points: int = 0, iterations: Optional[int] = None,
                  restarts: Optional[int] = None, decimation: Optional[float] = None,
                  optimizer: str = "powell", init: str = "fps", method: str = "variational",
                  format: str = "json", resume: bool = True,  # noqa: A002
                  threads: int = 0, max_protrusion: Any = None, max_er: Optional[float] = None,
                  max_spheres: Optional[int] = None, best_effort: bool = False,
                  repair_options: Dict[str, Any]) -> Dict[str, Any]:
    """The options of a batch as a plain dict (picklable, sent to the workers): the fit and
    repair options of ``sphereset fit``, the sphere file format, resuming, and the threads of
    one item's fit (0: all of the worker's cores). ``n`` None: the library's default (32). A
    tolerance (``max_protrusion``, a length or
    "P%" of the diagonal; ``max_er``; ``max_spheres``, the cap) makes each item's count the
    fewest that meet it, as ``sphereset fit --max-protrusion`` does (a manifest line may give
    its own; n and a tolerance on one line are refused, and so are a cap or ``best_effort`` that
    no limit goes with: checkToleranceRequest). An item no count up to its cap meets is
    an error item, or with ``best_effort`` its best count written (``tolerance_met`` false), as
    ``sphereset batch --best-effort``."""
    return {
        "tolerance": {"max_protrusion": max_protrusion, "max_er": max_er,
                      "max_spheres": max_spheres},
        # Parsed and checked by the library's fit table where the items are listed.
        "fit": {"n": n, "quality": quality, "seed": seed, "padding": padding,
                "points": points, "iterations": iterations, "restarts": restarts,
                "decimation": decimation, "optimizer": optimizer, "init": init,
                "method": method},
        **_repair_args(repair_options),
        "format": format, "resume": bool(resume),
        "threads": int(threads), "best_effort": bool(best_effort),
    }


def list_items(input_path: str, options: Dict[str, Any]) -> List[Dict[str, Any]]:
    """The items of a batch in run order: dicts {mesh, output, origin, fit}."""
    return _core._batch_items(os.fspath(input_path), options)


def process_item(item: Dict[str, Any], out_dir: str, options: Dict[str, Any]) -> str:
    """Fits one item into ``out_dir`` (or skips it when up to date) and returns its report line.
    This is the task each Dask worker runs."""
    return _core._batch_process(item, out_dir, options)


def _progress(done: int, total: int, t0: float, failed: int, quiet: bool) -> None:
    if quiet:
        return
    el = time.monotonic() - t0
    rate = done / el * 60.0 if el > 0 else 0.0
    left = (total - done) / (done / el) if done and el > 0 else float("nan")
    msg = (f"\rbatch: {done}/{total} items, {rate:.1f} items/min, "
           f"{left:.0f} s left, {failed} failed   ")
    sys.stderr.write(msg if sys.stderr.isatty() else msg.strip() + "\n")
    sys.stderr.flush()


def run_batch(input_path: str, out_dir: str, options: Dict[str, Any], client: Any,
              quiet: bool = False) -> List[str]:
    """Runs every item of ``input_path`` as one task of the dask.distributed ``client`` and
    writes OUT_DIR/report.jsonl in item order. Returns the report lines."""
    import json

    from distributed import as_completed

    out_dir = os.path.abspath(out_dir)
    _core._check_output_folder(out_dir, [os.fspath(input_path)])
    items = list_items(input_path, options)
    report = _core._BatchReport(out_dir)  # locks the folder for this run
    t0 = time.monotonic()
    # One task per mesh. A task is an effect (files written): its key is new for every run, so
    # that the scheduler never hands back the result of an earlier run's task.
    run = uuid.uuid4().hex
    futures = [client.submit(process_item, it, out_dir, options, key=f"sphereset-{run}-{i}",
                             pure=False) for i, it in enumerate(items)]
    index = {f.key: i for i, f in enumerate(futures)}
    lines: List[Optional[str]] = [None] * len(items)
    next_line = 0
    done = failed = 0
    for fut in as_completed(futures):
        i = index[fut.key]
        lines[i] = fut.result()
        fut.release()
        done += 1
        failed += json.loads(lines[i])["status"] == "error"
        # Whole lines, in item order: everything finished up to the first item still running.
        while next_line < len(items) and lines[next_line] is not None:
            report.append(lines[next_line])
            next_line += 1
        _progress(done, len(items), t0, failed, quiet)
    if not quiet and items and sys.stderr.isatty():
        sys.stderr.write("\n")
    report.finish()
    return [line for line in lines if line is not None]


def _exit_code(e: Exception) -> int:
    """The exit code `sphereset` gives the same error (the library's table, exit_codes.hpp)."""
    return getattr(e, "exit_code", 1)


def _parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog="python3 -m sphereset.batch",
        description="Fit every mesh of a folder or manifest on a Dask cluster, one task per mesh; "
                    "the same files and report as `sphereset batch`.")
    p.add_argument("input", help="folder of meshes, or a manifest (.csv or .jsonl)")
    p.add_argument("-o", "--output", required=True, help="output folder")
    where = p.add_mutually_exclusive_group(required=True)
    where.add_argument("--scheduler", help="address of a running Dask scheduler, e.g. "
                                           "tcp://host:8786 (or a scheduler JSON file)")
    where.add_argument("--local-workers", type=int, metavar="K",
                       help="start a local cluster of K worker processes (1 to the number of "
                            "cores)")
    p.add_argument("--threads", type=int, default=None,
                   help="threads of one item's fit (default: all of a remote worker's cores; "
                        "cores / K for --local-workers)")
    # The fit's options: one per row of the library's fit table, parsed by the library.
    for row in _core._fit_option_table():
        p.add_argument(*row["flag"].split(","), dest=row["name"], default=None,
                       metavar=row["type"].upper(),
                       help=f'{row["help"]} (default {row["default"]})')
    # The tolerance's options: one per row of the library's tolerance table.
    for row in _core._tolerance_option_table():
        p.add_argument(*row["flag"].split(","), dest=row["name"], default=None,
                       metavar=row["type"].upper() + ("[%]" if row["percent"] else ""),
                       help=f'{row["help"]} (default {row["default"]})')
    # The repair's options: one per row of the library's repair table, parsed by the library.
    for row in _core._repair_option_table():
        p.add_argument(*row["flag"].split(","), dest=row["name"], default=None,
                       metavar=row["type"].upper(),
                       help=f'{row["help"]} (default {row["default"]})')
    p.add_argument("--fill-cavities", dest="fill_cavities", action="store_true", default=True)
    p.add_argument("--keep-cavities", dest="fill_cavities", action="store_false")
    p.add_argument("--format", default="json", choices=["json", "txt", "sph", "yaml"],
                   help="sphere file format (default json)")
    p.add_argument("--force", action="store_true",
                   help="fit every item again, even those up to date")
    p.add_argument("--best-effort", dest="best_effort", action="store_true",
                   help="an item whose tolerance no count up to its cap meets: write the best "
                        "count found (tolerance_met false; exit 10) instead of failing the item")
    p.add_argument("-q", "--quiet", action="store_true", help="no progress on stderr")
    return p


def main(argv: Optional[List[str]] = None) -> int:
    a = _parser().parse_args(argv)
    try:
        repair = _repair_keyword_values(
            {row["name"]: getattr(a, row["name"]) for row in _core._repair_option_table()
             if getattr(a, row["name"]) is not None})
    except _core.Error as e:
        print(f"sphereset: {e}", file=sys.stderr)
        return _exit_code(e)
    repair["fill_cavities"] = a.fill_cavities
    from distributed import Client, LocalCluster

    cluster = None
    if a.local_workers is not None:
        # One fit per worker process: more processes than cores only share them, and a huge
        # count would start that many interpreters before the first item.
        cores = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else (
            os.cpu_count() or 1)
        if not 1 <= a.local_workers <= cores:
            print(f"sphereset: --local-workers {a.local_workers}: expected an integer from 1 to "
                  f"{cores} (the cores of this machine)", file=sys.stderr)
            return 2
        threads = a.threads if a.threads is not None else max(1, cores // a.local_workers)
        cluster = LocalCluster(n_workers=a.local_workers, threads_per_worker=1, processes=True,
                               dashboard_address=":0")
        client = Client(cluster)
    else:
        threads = a.threads if a.threads is not None else 0
        try:
            client = Client(a.scheduler, timeout=_SCHEDULER_TIMEOUT)
        except (OSError, TimeoutError, ValueError) as e:
            # An address that answers nothing, or is not one: one line, exit 2 (a bad option),
            # not a traceback.
            reason = str(e).splitlines()[0] if str(e) else type(e).__name__
            print(f"sphereset: --scheduler {a.scheduler}: cannot reach the scheduler ({reason})",
                  file=sys.stderr)
            return 2
    try:
        fit = {row["name"]: getattr(a, row["name"]) for row in _core._fit_option_table()}
        tolerance = {row["name"]: getattr(a, row["name"])
                     for row in _core._tolerance_option_table()}
        opts = batch_options(
            **{k: v for k, v in fit.items() if v is not None},
            **{k: v for k, v in tolerance.items() if v is not None}, **repair,
            format=a.format,
            resume=not a.force, threads=threads, best_effort=a.best_effort)
        try:
            lines = run_batch(a.input, a.output, opts, client, quiet=a.quiet)
        except _core.Error as e:
            print(f"sphereset: {e}", file=sys.stderr)
            return _exit_code(e)
    finally:
        client.close()
        if cluster is not None:
            cluster.close()
    # The summary and the exit code of `sphereset batch` (batch.hpp: batchEnd).
    end = _core._batch_end(lines, a.input, os.path.abspath(a.output))
    if not a.quiet:
        print(f"batch: {end['summary']} -> {_core._batch_report_path(os.path.abspath(a.output))}",
              file=sys.stderr)
    if end["exit_code"]:
        print(f"sphereset: {end['message']}", file=sys.stderr)
    return end["exit_code"]


if __name__ == "__main__":
    sys.exit(main())
