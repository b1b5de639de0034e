# SPDX-License-Identifier: MIT
"""docs/camera.md's validation table is the output of tools/validation_table.py
(the limiting magnitudes of the built-in cameras, computed on the runtime),
so that the document's numbers come from a command in the repository; and
the table's orderings hold: the zodiacal light and a warmer sensor cost
magnitudes, the threshold rule is stricter than SNR 5, the matched filter
reaches fainter than the brightest pixel."""
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "tools"))
import validation_table  # noqa: E402


def test_docs_hold_the_table():
    doc = (ROOT / "docs" / "camera.md").read_text()
    for t in (validation_table.table(), validation_table.goal_table(),
              validation_table.starlight_table()):
        assert t in doc, "docs/camera.md, Validation: paste the output of tools/validation_table.py"


def test_orderings():
    rows = validation_table.rows()
    for name, t, sky, temp, snr, thr, mf, pub in rows:
        assert thr < snr < mf, (name, t, sky)
    by = {(r[0], r[1], r[2], r[3]): r[4] for r in rows}
    tele = [v for k, v in by.items() if k[0] == "telescope-15cm"]
    assert tele[0] > tele[1] > tele[2]  # black, pole, 90 deg from the Sun
    ref = "-20 C (reference)"
    # the starlight costs magnitudes on top of the zodiacal light
    assert by[("telescope-15cm", 100.0, "zodiacal + starlight, ecliptic pole", ref)] < \
        by[("telescope-15cm", 100.0, "zodiacal, ecliptic pole", ref)]
    for t in (0.1, 0.5):
        assert by[("star-tracker", t, "black", "45 C")] < \
            by[("star-tracker", t, "black", "25 C (reference)")]
