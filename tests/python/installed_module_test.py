"""The Python module `shpack` as `cmake --install` leaves it, used from the installed prefix.

Run by tests/python/installed_module.cmake after it installed the build tree into
SHPACK_PREFIX, with PYTHONPATH holding only SHPACK_MODULE_DIR (the installed module's
folder): the module must be the installed one, find the installed OpenImageIO module (a PNG
is read through it), carry its version and licence, and give what the installed command
gives for the installed bundled map and for the PNG.
"""

import importlib.metadata
import json
import os
import pathlib
import struct
import subprocess
import tempfile
import unittest
import zlib

import shpack

PREFIX = pathlib.Path(os.environ["SHPACK_PREFIX"]).resolve()
MODULE_DIR = pathlib.Path(os.environ["SHPACK_MODULE_DIR"]).resolve()
CLI = PREFIX / "bin" / "shpack"
STUDIO = PREFIX / "share" / "shpack" / "hdri" / "studio.exr"


def write_png(path, width, height):
    """An 8-bit RGB PNG, a gradient: no colour chunk, so it is read as sRGB."""
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))

    rows = b"".join(b"\0" + bytes(v for x in range(width) for v in (x * 255 // width, y * 255 // height, 96))
                    for y in range(height))
    with open(path, "wb") as out:
        out.write(b"\x89PNG\r\n\x1a\n")
        out.write(chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)))
        out.write(chunk(b"IDAT", zlib.compress(rows)))
        out.write(chunk(b"IEND", b""))


def cli_document(path):
    run = subprocess.run([str(CLI), "convert", str(path)], capture_output=True, text=True, check=False)
    if run.returncode != 0:
        raise AssertionError(f"{CLI} convert {path}: exit {run.returncode}: {run.stderr}")
    return json.loads(run.stdout)


class InstalledModule(unittest.TestCase):
    def test_is_the_installed_module(self):
        self.assertEqual(pathlib.Path(shpack.__file__).resolve().parent, MODULE_DIR / "shpack")

    def test_dask_module_is_installed_and_finds_the_installed_command(self):
        import shpack.dask  # pylint: disable=import-outside-toplevel

        self.assertEqual(pathlib.Path(shpack.dask.__file__).resolve().parent, MODULE_DIR / "shpack")
        self.assertEqual(pathlib.Path(shpack.dask.find_command()).resolve(), CLI.resolve())

    def test_version_and_licence(self):
        self.assertEqual(shpack.__license__, "Apache-2.0")
        self.assertEqual(importlib.metadata.version("shpack"), shpack.__version__)
        self.assertEqual(importlib.metadata.metadata("shpack")["License"], "Apache-2.0")
        for name in ("LICENSE", "NOTICE"):
            self.assertTrue((PREFIX / "share" / "doc" / "shpack" / name).is_file(), name)

    def test_bundled_map_as_the_command_reads_it(self):
        self.assertEqual(shpack.convert(STUDIO), cli_document(STUDIO))

    def test_png_through_the_installed_oiio_module(self):
        with tempfile.TemporaryDirectory() as folder:
            png = pathlib.Path(folder) / "gradient.png"
            write_png(png, 64, 32)
            document = shpack.convert(png)
            self.assertEqual(document["source"]["width"], 64)
            self.assertEqual(document, cli_document(png))


if __name__ == "__main__":
    unittest.main()
