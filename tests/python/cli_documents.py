"""FreeCAD documents the command-line tests run `popup` on, built headless through popupwb.make.

two_cards.FCStd holds two A5 cards (148 mm along the fold, pages 105 mm deep):
  Good            a tent with foot 20 + slope 30 = 50 mm from the fold: closes inside the page;
  Bad, labelled "Tall tent card"
                  a tent with foot 30 + slope 80 = 110 mm: closed, it sticks out of the 105 mm
                  page by 5 mm (not enclosed, everything else fine).
huge.FCStd holds a 300 x 300 mm custom card: open, 300 x 600 mm, larger than every paper preset.
card.FCStd is the demo's A4 card (tools/run_demo.py, BUILD_CARD): open, 210 x 297 mm.
"""

import os
import textwrap

from cli_runner import load_tool, run_freecad_script

PAGE_DEPTH = 105.0  # mm, an A5 card's page
BAD_OVERHANG = 30.0 + 80.0 - PAGE_DEPTH  # mm: foot + slope of the tall tent beyond the page

CARDS = textwrap.dedent(
    """
    import sys
    import FreeCAD
    from popupwb import make

    folder = sys.argv[1]
    doc = FreeCAD.newDocument("two_cards")
    good = make.make_card(doc, preset="A5", name="Good")
    make.make_tent_fold(
        good, name="Tent", offset=40.0, width=60.0, foot=20.0, foot_backdrop=20.0, slope=30.0
    )
    bad = make.make_card(doc, preset="A5", name="Bad")
    bad.Label = "Tall tent card"
    make.make_tent_fold(
        bad, name="TallTent", offset=40.0, width=60.0, foot=30.0, foot_backdrop=30.0, slope=80.0
    )
    doc.recompute()
    broken = [o.Label for o in doc.Objects if "Invalid" in o.State]
    if broken:
        sys.exit(f"features in error: {broken}")
    doc.saveAs(folder + "/two_cards.FCStd")

    doc = FreeCAD.newDocument("huge")
    make.make_card(doc, width=300.0, depth=300.0, name="Huge")
    doc.recompute()
    doc.saveAs(folder + "/huge.FCStd")
    """
)


def build_cards(folder, home):
    """two_cards.FCStd and huge.FCStd in `folder`."""
    run_freecad_script(CARDS, folder, home=home)
    return folder


def build_demo_card(folder, home):
    """The demo's card.FCStd in `folder`, built by the demo's own script."""
    run_demo = load_tool("run_demo")
    paths = [os.path.join(folder, name) for name in ("card.FCStd", "validity.json", "validity.txt")]
    run_freecad_script(run_demo.BUILD_CARD, *paths, home=home)
    return paths[0]
