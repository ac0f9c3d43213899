"""The documentation's sources: docs/conf.py documents every public routine, the
docstrings parse as numpydoc, and the gallery's scripts draw drawing-sheet figures.
The build itself (sphinx-build -W) is scripts/build-docs.sh, run by .ci/run."""

from __future__ import annotations

import importlib
import importlib.util
import runpy
import sys
import warnings
from pathlib import Path

import pytest

import sarkp

sys.path.insert(0, str(Path(__file__).resolve().parent))   # --import-mode=importlib
DOCS = Path(__file__).resolve().parents[1] / "docs"


def _conf():
    spec = importlib.util.spec_from_file_location("sarkp_docs_conf", DOCS / "conf.py")
    conf = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(conf)
    return conf


def _documented(conf):
    pages = {**conf.CHAPTERS, **conf.SUPPORT, "mechanism": conf.MECHANISM[1:]}
    out = {}
    for title, module_name in pages.values():
        try:
            module = importlib.import_module(module_name)
        except ImportError:
            continue
        for name in conf._public(module):
            out[name] = getattr(module, name)
    return out


def test_every_public_name_of_sarkp_has_a_page():
    documented = _documented(_conf())
    missing = [n for n in sarkp.__all__ if callable(getattr(sarkp, n)) and n not in documented]
    assert missing == []
    # every routine of Table 33 (and the extensions) among them
    assert {"GELG", "DPRM1", "DKNMA5", "DZKNDV", "DMHVK", "DGMZVN", "DUGL6"} <= set(documented)


def test_docstrings_parse_as_numpydoc():
    docscrape = pytest.importorskip("numpydoc.docscrape")
    import inspect
    for name, value in _documented(_conf()).items():
        if not callable(value) or not (value.__doc__ or "").strip():
            continue
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            if inspect.isclass(value):
                docscrape.ClassDoc(value)
            else:
                doc = docscrape.FunctionDoc(value)
                if "Parameters" in value.__doc__:
                    assert doc["Parameters"], name


@pytest.mark.parametrize("script", sorted(p.name for p in (DOCS / "examples").glob("plot_*.py")))
def test_gallery_scripts_draw_drawing_sheets(script, capsys):
    pytest.importorskip("matplotlib")
    from matplotlib.figure import Figure
    from test_plots import sheet_problems
    names = runpy.run_path(str(DOCS / "examples" / script), run_name="__main__")
    figures = {id(v): v for v in names.values() if isinstance(v, Figure)}
    assert figures, "the script draws nothing"
    for figure in figures.values():
        assert sheet_problems(figure) == []
