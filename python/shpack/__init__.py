"""Unity L2 spherical harmonics from HDR environment maps (shpack).

project() and convert() come from the extension shpack._shpack (python/shpack_module.cpp),
which returns the documents `shpack convert` writes. shpack.dask bakes a scene on a Dask
cluster (docs/scale.md); it is imported only when asked for, so `import shpack` does not
load Dask.
"""

from ._shpack import __license__, __version__, convert, project

__all__ = ["convert", "project"]
