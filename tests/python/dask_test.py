"""shpack.dask (python/shpack/dask.py) on LocalClusters of this machine.

The merged bake must be `shpack bake`'s: the same images byte for byte and the same JSON but
for the timings, also when a worker is killed while it bakes a shard (the scheduler runs that
shard again elsewhere). Run by ctest (tests/python/CMakeLists.txt) with Debian's
/usr/bin/python3 and python3-distributed; SHPACK_CLI names the command, PYTHONPATH the
package.
"""

import json
import os
import pathlib
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
import time
import unittest

import distributed

import shpack.dask

CLI = os.environ["SHPACK_CLI"]

# A floor with a lightmap and a box on it, probes around: every shard holds probes or texels.
SCENE = {
    "environment": {"type": "gradient", "zenith": [0.2, 0.3, 0.8], "horizon": 0.7, "ground": 0.2},
    "lights": [{"type": "directional", "direction": [-0.4, -0.8, -0.3], "irradiance": 5, "angular_diameter_deg": 4}],
    "geometry": [
        {"type": "plane", "name": "floor", "position": [0, 0, 0], "right": [0, 0, 1], "up": [1, 0, 0],
         "size": [4, 4], "albedo": 0.5, "lightmap": {"resolution": [12, 12]}},
        {"type": "box", "min": [-0.5, 0, -0.5], "max": [0.5, 1, 0.5], "albedo": 0.6}],
    "probes": [[0, 0.5, 0], [1.5, 0.5, 1.5], [-1.5, 1, 0.5], [0.8, 2, -1.2]],
    "effects": ["direct", "environment", "shadows", "sky_occlusion", "bounce:1"],
    "settings": {"shadow_samples": 16, "sky_samples": 64, "bounce_samples": 64},
}


def without_timings(value):
    """The document without what measures time (keys ending in _ms or _per_s)."""
    if isinstance(value, dict):
        return {k: without_timings(v) for k, v in value.items() if not k.endswith(("_ms", "_per_s"))}
    if isinstance(value, list):
        return [without_timings(v) for v in value]
    return value


def local_cluster(workers):
    return distributed.LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                                    dashboard_address=None)


class DaskBake(unittest.TestCase):
    def setUp(self):
        self.folder = pathlib.Path(tempfile.mkdtemp(prefix="shpack-dask-test-"))
        self.addCleanup(shutil.rmtree, self.folder, ignore_errors=True)

    def write_scene(self, scene, name="scene.json"):
        path = self.folder / name
        path.write_text(json.dumps(scene))
        return path

    def one_machine(self, scene):
        folder = self.folder / "one"
        folder.mkdir(exist_ok=True)
        subprocess.run([CLI, "bake", str(scene), "-o", str(folder / "out.json"), "--quiet"], check=True)
        return folder

    def assert_same_bake(self, one, merged):
        for name in ("floor.SHAr.exr", "floor.SHAg.exr", "floor.SHAb.exr", "floor.texels.exr"):
            self.assertEqual((one / name).read_bytes(), (merged / name).read_bytes(), name)
        for name in ("out.json", "floor.lightmap.json"):
            self.assertEqual(without_timings(json.loads((one / name).read_text())),
                             without_timings(json.loads((merged / name).read_text())), name)

    def test_merged_shards_are_the_one_machine_bake(self):
        scene = self.write_scene(SCENE)
        one = self.one_machine(scene)
        merged = self.folder / "merged"
        merged.mkdir()
        with local_cluster(2) as cluster, distributed.Client(cluster) as client:
            document = shpack.dask.bake(scene, merged / "out.json", client=client, shards=5, progress=False)
        self.assertEqual(len(document["probes"]), 4)
        self.assert_same_bake(one, merged)

    def test_a_worker_killed_mid_bake_has_its_shard_baked_again(self):
        # Slower shards (a few seconds each on one thread), so that the kill lands inside one.
        slow = dict(SCENE, settings={"shadow_samples": 64, "sky_samples": 512, "bounce_samples": 1024})
        slow["geometry"] = [dict(SCENE["geometry"][0], lightmap={"resolution": [24, 24]}), SCENE["geometry"][1]]
        scene = self.write_scene(slow)
        one = self.one_machine(scene)
        merged = self.folder / "merged"
        merged.mkdir()
        with local_cluster(2) as cluster, distributed.Client(cluster) as client:
            pids = client.run(os.getpid)
            outcome = {}

            def run():
                try:
                    outcome["document"] = shpack.dask.bake(scene, merged / "out.json", client=client, shards=4,
                                                           progress=False)
                except Exception as error:  # reported by the assertions below
                    outcome["error"] = error

            baking = threading.Thread(target=run)
            baking.start()
            victim = None
            deadline = time.monotonic() + 60
            while victim is None and time.monotonic() < deadline:
                busy = [worker for worker, keys in client.processing().items() if keys]
                if busy:
                    victim = busy[0]
                time.sleep(0.05)
            self.assertIsNotNone(victim, "no worker took a shard")
            time.sleep(0.5)  # inside the shard's bake
            os.kill(pids[victim], signal.SIGKILL)
            baking.join(timeout=240)
            self.assertFalse(baking.is_alive())
        self.assertNotIn("error", outcome, outcome.get("error"))
        self.assert_same_bake(one, merged)

    def test_command_line_bakes_on_a_local_cluster_and_fails_in_one_line(self):
        scene = self.write_scene(SCENE)
        one = self.one_machine(scene)
        merged = self.folder / "merged"
        merged.mkdir()
        env = dict(os.environ, SHPACK_CLI=CLI)
        run = subprocess.run([sys.executable, "-m", "shpack.dask", str(scene), "-o", str(merged / "out.json"),
                              "--shards", "3"], capture_output=True, text=True, env=env, check=False)
        self.assertEqual(run.returncode, 0, run.stderr)
        self.assertEqual(run.stderr.count("baked ("), 3, run.stderr)  # one line per shard
        self.assert_same_bake(one, merged)
        missing = self.folder / "missing.json"
        run = subprocess.run([sys.executable, "-m", "shpack.dask", str(missing), "-o", str(self.folder / "x.json"),
                              "--shards", "2"], capture_output=True, text=True, env=env, check=False)
        self.assertEqual(run.returncode, 1)
        lines = [line for line in run.stderr.splitlines() if line.startswith("shpack.dask:")]
        self.assertEqual(len(lines), 1, run.stderr)
        self.assertIn(str(missing), lines[0])
        self.assertFalse((self.folder / "x.json").exists())


if __name__ == "__main__":
    unittest.main()
