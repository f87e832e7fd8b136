"""shpack.dask: `shpack bake` past one machine, on Dask distributed (docs/scale.md).

    python3 -m shpack.dask SCENE.json -o OUT.json [--scheduler tcp://HOST:PORT] [--shards N]

or, from Python, bake(scene, output, client=...). The bake is cut into N shards (`shpack bake
SCENE --shard K/N`: probes and lightmap texels balanced by their estimated rays). Each shard
is one Dask task that runs the shpack command on a worker and returns its part file's bytes,
so the workers need the scene and the files it names at the same path (a shared folder) but
no shared output folder. When a worker is lost mid-bake, the scheduler runs its shard again
on another: a shard's part is the same wherever and however often it runs. The client writes
the parts to a temporary folder and runs `shpack merge`, which writes exactly what `shpack
bake SCENE -o OUT` writes (the timings aside).

Without a client or --scheduler, a LocalCluster of this machine's cores is started (one
worker process per core, one thread each) and closed at the end. Dask is imported here only.
"""

import argparse
import ctypes
import json
import os
import pathlib
import shutil
import signal
import subprocess
import sys
import tempfile

import distributed


class BakeError(RuntimeError):
    """A shard or the merge failed; the message is shpack's one line."""


def find_command(explicit=None):
    """The shpack command: `explicit`, $SHPACK_CLI, the one installed with this package
    (<prefix>/bin/shpack beside <prefix>/lib/python3/dist-packages/shpack), or shpack on PATH."""
    if explicit:
        return str(explicit)
    if os.environ.get("SHPACK_CLI"):
        return os.environ["SHPACK_CLI"]
    here = pathlib.Path(__file__).resolve().parent
    for prefix in here.parents:
        candidate = prefix / "bin" / "shpack"
        if candidate.is_file() and os.access(candidate, os.X_OK):
            return str(candidate)
    found = shutil.which("shpack")
    if found is None:
        raise BakeError("the shpack command is neither beside this module nor on PATH (set SHPACK_CLI)")
    return found


def _die_with_parent():
    """In the shard's process: killed when its worker process dies (Linux PR_SET_PDEATHSIG), so
    that a lost worker leaves no bake running that nobody waits for."""
    try:
        ctypes.CDLL(None, use_errno=True).prctl(1, signal.SIGKILL)  # PR_SET_PDEATHSIG = 1
    except (OSError, AttributeError):
        pass


def _scratch():
    """A folder for one shard's part: the worker's own local directory if there is one."""
    try:
        base = distributed.get_worker().local_directory
    except ValueError:  # not in a worker (called directly)
        base = None
    return tempfile.TemporaryDirectory(prefix="shpack-shard-", dir=base)


def bake_shard(scene, index, count, threads=1, command=None):
    """Shard index/count of `scene` baked here; returns the part file's bytes. Runs as a task."""
    command = find_command(command)
    with _scratch() as folder:
        part = os.path.join(folder, "part")
        run = subprocess.run(
            [command, "bake", str(scene), "--shard", f"{index}/{count}", "--threads", str(threads), "--quiet",
             "-o", part],
            capture_output=True, text=True, check=False, preexec_fn=_die_with_parent)
        if run.returncode != 0:
            raise BakeError(f"shard {index}/{count}: {run.stderr.strip()}")
        return pathlib.Path(part).read_bytes()


def _merge(command, scene, parts, output, lightmap_dir, output_format, window):
    with tempfile.TemporaryDirectory(prefix="shpack-merge-") as folder:
        files = []
        for index, data in sorted(parts.items()):
            path = os.path.join(folder, f"part{index}")
            pathlib.Path(path).write_bytes(data)
            files.append(path)
        args = [command, "merge", *files, "--scene", str(scene), "-o", str(output)]
        if lightmap_dir is not None:
            args += ["--lightmap-dir", str(lightmap_dir)]
        if output_format is not None:
            args += ["--format", output_format]
        if window is not None:
            args += ["--window", window]
        run = subprocess.run(args, capture_output=True, text=True, check=False)
        if run.returncode != 0:
            raise BakeError(f"merge: {run.stderr.strip()}")
        sys.stderr.write(run.stderr)  # the bake's warnings (probes inside geometry, capped ones)


def bake(scene, output, client=None, shards=None, threads=1, command=None, lightmap_dir=None, output_format=None,
         window=None, progress=True, workers=None):
    """Bakes `scene` on the cluster of `client` (a distributed.Client; None: a LocalCluster of
    `workers` worker processes, None: this machine's cores) in `shards` shards (None: twice
    the cluster's threads), each shard with `threads` threads of its worker (0: all of its
    cores), and merges the parts into
    `output` (and the lightmaps' files, in `lightmap_dir` or beside it). Returns the merged
    document (the JSON of `shpack bake`). One line per finished shard goes to stderr when
    `progress`. Raises BakeError with shpack's message if a shard or the merge fails."""
    scene = pathlib.Path(scene).resolve()
    own = None
    if client is None:
        cluster = distributed.LocalCluster(n_workers=workers or os.cpu_count() or 1, threads_per_worker=1,
                                           processes=True, dashboard_address=None)
        own = (cluster, distributed.Client(cluster))
        client = own[1]
    try:
        if shards is None:
            shards = max(1, 2 * sum(client.nthreads().values()))
        if shards < 1:
            raise BakeError("shards must be at least 1")
        indices = range(1, shards + 1)
        # pure=False: a new key per bake, never a part kept from an earlier bake of a changed scene.
        futures = client.map(bake_shard, [str(scene)] * shards, indices, [shards] * shards, [threads] * shards,
                             [command] * shards, pure=False)
        index_of = {future.key: index for future, index in zip(futures, indices)}
        parts = {}
        for done, future in enumerate(distributed.as_completed(futures), start=1):
            index = index_of[future.key]
            try:
                parts[index] = future.result()
            except BakeError:
                client.cancel(futures)
                raise
            if progress:
                print(f"shpack.dask: shard {index}/{shards} baked ({done} of {shards})", file=sys.stderr, flush=True)
        _merge(find_command(command), scene, parts, output, lightmap_dir, output_format, window)
    finally:
        if own is not None:
            own[1].close()
            own[0].close()
    with open(output, encoding="utf-8") as merged:
        return json.load(merged)


def main(argv=None):
    parser = argparse.ArgumentParser(
        prog="python3 -m shpack.dask",
        description="Bake a scene on a Dask cluster: shpack bake --shard on the workers, shpack merge here.")
    parser.add_argument("scene", help="the scene file, at the same path on every worker")
    parser.add_argument("-o", "--output", required=True, help="the output JSON file")
    parser.add_argument("--scheduler", help="tcp://HOST:PORT of a running dask scheduler (default: a LocalCluster)")
    parser.add_argument("--workers", type=int, help="without --scheduler: the LocalCluster's worker processes "
                        "(default: this machine's cores)")
    parser.add_argument("--shards", type=int, help="shards to cut the bake into (default: twice the workers' threads)")
    parser.add_argument("--threads", type=int, default=1, help="threads per shard (default 1; 0: all of a worker's cores)")
    parser.add_argument("--lightmap-dir", help="folder of the lightmaps' files (default: the output's folder)")
    parser.add_argument("--format", dest="output_format", choices=["full", "unity-probes"], help="as shpack bake's")
    parser.add_argument("--window", help="as shpack bake's")
    parser.add_argument("--shpack", help="the shpack command (default: the one installed with this module)")
    parser.add_argument("--quiet", action="store_true", help="no line per shard")
    args = parser.parse_args(argv)
    if args.shards is not None and args.shards < 1:
        parser.error("--shards must be at least 1")
    if args.threads < 0:
        parser.error("--threads must be at least 0")
    if args.workers is not None and (args.workers < 1 or args.scheduler):
        parser.error("--workers takes a count of at least 1, without --scheduler")
    client = distributed.Client(args.scheduler) if args.scheduler else None
    try:
        bake(args.scene, args.output, client=client, shards=args.shards, threads=args.threads, command=args.shpack,
             lightmap_dir=args.lightmap_dir, output_format=args.output_format, window=args.window,
             progress=not args.quiet, workers=args.workers)
    except (BakeError, OSError) as error:
        print(f"shpack.dask: {error}", file=sys.stderr)
        return 1
    finally:
        if client is not None:
            client.close()
    return 0


if __name__ == "__main__":
    # Run as shpack.dask, not __main__: the tasks then name their function by its module, which
    # a worker imports, rather than carrying this file's copy of it.
    from shpack.dask import main as package_main

    sys.exit(package_main())
