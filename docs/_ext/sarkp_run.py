"""Run the Python code of the documentation's pages and show what it prints and draws.

Every ```` ```python ```` block of a Markdown page of docs/ (the concepts, the tutorial,
the page for teachers, ...) runs when the page is read, in order, all blocks of a page in
one namespace, in a scratch folder.  After each block the page shows what the block
printed (a ``text`` block headed "Output") and every matplotlib Figure the block bound to
a name (saved as a PNG into ``docs/_generated/img``).  A block that raises fails the
build, naming the page and the block's first line; so does a warning the page does not
catch (deprecations of other packages aside).

The same function, :func:`run_page`, is what ``tests/test_docs.py`` calls to check that
every code block of the docs runs.
"""

from __future__ import annotations

import contextlib
import io
import os
import re
import tempfile
import traceback
import warnings
from pathlib import Path

#: a fenced Python block at the start of a line (its fence may be indented: a list item)
BLOCK = re.compile(r"^( *)```python[ \t]*\n(.*?)^\1```[ \t]*$", re.M | re.S)


class PageError(RuntimeError):
    """A code block of a documentation page failed."""


@contextlib.contextmanager
def _inside(folder):
    here = os.getcwd()
    os.chdir(folder)
    try:
        yield
    finally:
        os.chdir(here)


def _figures(namespace, seen):
    from matplotlib.figure import Figure
    out = []
    for value in list(namespace.values()):
        if isinstance(value, Figure) and id(value) not in seen:
            seen.add(id(value))
            out.append(value)
    return out


def _alt(figure) -> str:
    """A figure's alt text: its suptitle, else its first axes' title."""
    if figure._suptitle is not None and figure._suptitle.get_text().strip():
        text = figure._suptitle.get_text()
    else:
        text = next((ax.get_title() for ax in figure.axes if ax.get_title().strip()),
                    "a figure drawn by the code above")
    return " ".join(text.split()).replace("[", "(").replace("]", ")")


def run_page(text: str, name: str, image_dir: Path | None = None,
             image_prefix: str = "") -> tuple[str, list]:
    """Run the ```python blocks of ``text`` (a page called ``name``); return the page
    with each block followed by what it printed and drew, and the figures drawn.

    ``image_dir``: where the figures are saved as ``<name>-<k>.png`` (None: not saved);
    ``image_prefix``: the path the page refers to them by.
    """
    namespace: dict = {"__name__": f"__docs_{name}__"}
    seen: set[int] = set()
    figures = []
    parts, last = [], 0
    count = 0
    scratch = tempfile.mkdtemp(prefix=f"sarkp-docs-{name}-")
    for number, match in enumerate(BLOCK.finditer(text), start=1):
        indent, code = match.group(1), match.group(2)
        code = "\n".join(line[len(indent):] for line in code.splitlines())
        output = io.StringIO()
        first = next((line for line in code.splitlines() if line.strip()), "")
        with contextlib.redirect_stdout(output), _inside(scratch), \
                warnings.catch_warnings():
            warnings.simplefilter("error")          # a page's code warns only on purpose
            for category in (DeprecationWarning, PendingDeprecationWarning):
                warnings.simplefilter("default", category)   # other packages' business
            try:
                exec(compile(code, f"<{name}.md, block {number}>", "exec"), namespace)
            except Exception as exc:
                raise PageError(f"docs/{name}.md, code block {number} ({first!r}) "
                                f"raised:\n{traceback.format_exc()}") from exc
        parts.append(text[last:match.end()])
        last = match.end()
        printed = output.getvalue().rstrip("\n")
        if printed:
            parts += ["\n\n", indent, "*Output:*\n\n", indent, "```text\n"]
            parts += [indent + line + "\n" for line in printed.splitlines()]
            parts += [indent, "```"]
        for figure in _figures(namespace, seen):
            count += 1
            figures.append(figure)
            if image_dir is not None:
                image_dir.mkdir(parents=True, exist_ok=True)
                file = f"{name.replace('/', '-')}-{count}.png"
                figure.savefig(image_dir / file, dpi=100)
                parts += ["\n\n", indent, f"![{_alt(figure)}]({image_prefix}{file})"]
    parts.append(text[last:])
    return "".join(parts), figures


def has_code(text: str) -> bool:
    return BLOCK.search(text) is not None


# ---- the Sphinx side ------------------------------------------------------------------

def _source_read(app, docname, source):
    path = Path(app.env.doc2path(docname))
    if path.suffix != ".md" or "_generated" in path.parts or not has_code(source[0]):
        return
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    image_dir = Path(app.srcdir) / "_generated" / "img"
    depth = docname.count("/")
    text, figures = run_page(source[0], docname, image_dir,
                             "../" * depth + "_generated/img/")
    for figure in figures:
        plt.close(figure)
    source[0] = text


def _always_outdated(app, env, added, changed, removed):
    """Pages with code are read again on every build: their output is sarkp's today."""
    out = []
    for docname in env.found_docs:
        path = Path(env.doc2path(docname))
        if path.suffix == ".md" and "_generated" not in path.parts and \
                has_code(path.read_text(encoding="utf-8")):
            out.append(docname)
    return out


def setup(app):
    app.connect("source-read", _source_read)
    app.connect("env-get-outdated", _always_outdated)
    return {"parallel_read_safe": False, "parallel_write_safe": True}
