"""The gallery's image scraper (named in docs/conf.py, so that Sphinx can pickle it).

sarkp.plot draws on matplotlib Figures outside pyplot, which sphinx-gallery's own
matplotlib scraper does not see: this one collects every Figure the example's code has
bound to a name, each once, and saves it as the gallery's image.
"""

from __future__ import annotations

_SEEN: set[int] = set()


def scrape(block, block_vars, gallery_conf):
    from matplotlib.figure import Figure
    from sphinx_gallery.scrapers import figure_rst
    figures = {id(v): v for v in list(block_vars["example_globals"].values())
               if isinstance(v, Figure) and id(v) not in _SEEN}.values()
    paths = []
    for figure, path in zip(figures, block_vars["image_path_iterator"]):
        _SEEN.add(id(figure))
        figure.savefig(path, dpi=110)
        paths.append(path)
    return figure_rst(paths, gallery_conf["src_dir"])
