"""The README's picture of the page (docs/refresh.sh): the worksheet's
four-bar in headless Chromium through `linkage serve`, five target points
of its coupler curve placed, a synthesis run in the page's worker, its
designs listed.

    python tests/web/page_figure.py docs/figures/web/page.png
"""

import sys

from browser import Server, Tab


def main(out):
    server = Server()
    tab = Tab(1280, 1260)
    try:
        tab.open(server.url)
        tab.evaluate(
            "(() => { const { info, sweep } = linkagePage;"
            " const g = info.pointNames.indexOf('G3'), p = info.pointNames.length;"
            " document.getElementById('design-targets').value = [0, 72, 144, 216, 288].map((k) =>"
            " `${sweep.points[k * 2 * p + 2 * g]}, ${sweep.points[k * 2 * p + 2 * g + 1]}`).join('\\n');"
            " document.getElementById('design-point').value = 'G3'; linkagePage.freeBounds();"
            " document.getElementById('design-starts').value = '32'; linkagePage.draw(linkagePage.current);"
            " document.getElementById('design-run').click(); })()")
        tab.wait("document.body.dataset.designDone", 120)
        tab.evaluate("scrollTo(0, 0)")
        tab.screenshot(out)
    finally:
        tab.close()
        server.close()


if __name__ == "__main__":
    main(sys.argv[1])
