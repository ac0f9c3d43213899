"""The gallery's image scraper (named in docs/conf.py, so that Sphinx can pickle it).

sarkp.plot draws on matplotlib Figures outside pyplot, which sphinx-gallery's own
matplotlib scraper does not see: this one collects every Figure the example's code has
bound to a name, each once, and saves it as the gallery's image.  An animation written
by ``MechanismResult.animate`` (a ``.gif``: the example binds the path ``animate``
returns to a name) is copied in as an image too.
"""

from __future__ import annotations

import shutil
from pathlib import Path

_SEEN: set = set()


def _animations(values):
    out = []
    for v in values:
        if isinstance(v, (str, Path)) and str(v).endswith(".gif") and Path(v).is_file():
            key = ("gif", str(Path(v).resolve()), Path(v).stat().st_mtime_ns)
            if key not in _SEEN:
                _SEEN.add(key)
                out.append(Path(v))
    return out


def scrape(block, block_vars, gallery_conf):
    from matplotlib.figure import Figure
    from sphinx_gallery.scrapers import figure_rst
    values = list(block_vars["example_globals"].values())
    figures = {id(v): v for v in values
               if isinstance(v, Figure) and id(v) not in _SEEN}.values()
    paths = []
    iterator = block_vars["image_path_iterator"]
    for figure in figures:
        path = next(iterator)
        _SEEN.add(id(figure))
        figure.savefig(path, dpi=110)
        paths.append(path)
    for gif in _animations(values):
        path = str(Path(next(iterator)).with_suffix(".gif"))
        shutil.copyfile(gif, path)
        paths.append(path)
    return figure_rst(paths, gallery_conf["src_dir"])
