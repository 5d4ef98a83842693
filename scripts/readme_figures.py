#!/usr/bin/env python3
"""Extracts figures of a run's report.html as standalone SVG files (the README's figures).

Each figure of the report is an inline <svg> with its id (fig-alignment, fig-navigation, ...);
a standalone file needs the report's stylesheet inlined and a background.

    /usr/bin/python3 scripts/readme_figures.py RUN_DIR OUT_DIR fig-alignment:run_alignment fig-navigation:run_navigation
"""
import pathlib
import re
import sys


def main() -> int:
    if len(sys.argv) < 4:
        print(__doc__, file=sys.stderr)
        return 2
    report = pathlib.Path(sys.argv[1]) / "report.html"
    out = pathlib.Path(sys.argv[2])
    html = report.read_text()
    style = re.search(r"<style>(.*?)</style>", html, re.S)
    if style is None:
        print(f"{report}: no <style> in the head", file=sys.stderr)
        return 1
    out.mkdir(parents=True, exist_ok=True)
    for request in sys.argv[3:]:
        figure_id, _, name = request.partition(":")
        at = html.find(f'<svg id="{figure_id}"')
        if at < 0:
            print(f"{report}: no figure with id {figure_id}", file=sys.stderr)
            return 1
        start = at
        end = html.find("</svg>", start) + len("</svg>")
        svg = html[start:end]
        open_end = svg.find(">") + 1
        head = svg[:open_end]
        if "xmlns=" not in head:
            head = head.replace("<svg", '<svg xmlns="http://www.w3.org/2000/svg"', 1)
        text = ('<?xml version="1.0" encoding="UTF-8"?>\n' + head + "\n<style>\n" + style.group(1) +
                '\n</style>\n<rect width="100%" height="100%" fill="#ffffff"/>' + svg[open_end:] + "\n")
        (out / f"{name}.svg").write_text(text)
        print(f"{out / (name + '.svg')}: {figure_id} of {report}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
