"""The report's "Recorded runs" section: the players the main job writes into
reports/players/ (tests/viewer/check_player.py's index.json) appear in index.html, and a
report without them has no such section. Run:
/usr/bin/python3 -m unittest discover -s traceability/tests -t .
"""
import json
import os
import shutil
import tempfile
import unittest

from traceability.tests.test_harness import REPO, run_harness

ENTRIES = [
    {"name": "pyramid20", "scene": "examples/scenes/pyramid20.json", "options": "--every 1",
     "page": "pyramid20.html", "bytes": 222818, "frames": 601, "bodies": 211, "joints": 0,
     "description": "A pyramid <of> boxes", "screenshot": "pyramid20.png",
     "result": "OK: 601 frames, 1688 states within half a quantum"},
    {"name": "collision_im3", "scene": "examples/scenes/collision_im3.json", "options": "--every 1",
     "page": "collision_im3.html", "bytes": 39260, "frames": 61, "bodies": 2, "joints": 0,
     "result": "failed: collision_im3: background colour where bodies should be"},
    {"name": "rain", "scene": "examples/scenes/rain.json", "options": "--every 10",
     "page": "rain.html", "bytes": 1422100, "result": "not checked: Chromium is not installed"},
]


class PlayersSection(unittest.TestCase):
    def render(self, entries):
        tmp = tempfile.mkdtemp(prefix="trace-players-")
        self.addCleanup(shutil.rmtree, tmp, True)
        out = os.path.join(tmp, "reports")
        if entries is not None:
            os.makedirs(os.path.join(out, "players"))
            with open(os.path.join(out, "players", "index.json"), "w", encoding="utf-8") as fh:
                fh.write(entries if isinstance(entries, str) else json.dumps(entries))
        run_harness(REPO, out)
        with open(os.path.join(out, "index.html"), encoding="utf-8") as fh:
            return fh.read()

    def test_players_listed_and_embedded(self):
        page = self.render(ENTRIES)
        self.assertIn('id="players"', page)
        self.assertIn('<a href="#players">Recorded runs</a>', page)
        # The featured V&V scene (IM3's collision) plays first, in the frame and the picker.
        self.assertIn('<iframe id="player-frame" class="player-frame" src="players/collision_im3.html"', page)
        picker = page[page.index('id="player-pick"'):page.index("</select>")]
        self.assertLess(picker.index("collision_im3"), picker.index("pyramid20"))
        self.assertLess(picker.index("pyramid20"), picker.index("rain"))
        for needle in ('href="players/pyramid20.html"', 'src="players/pyramid20.png"',
                       "601 frames", "211 bodies", "0.22 MB", "1.42 MB", "39 kB",
                       "A pyramid &lt;of&gt; boxes", "<code class=\"nowrap\">--every 10</code>"):
            self.assertIn(needle, page)
        rows = page[page.index('id="players"'):]
        self.assertIn('st-ok" title=', rows)      # pyramid20 passed
        self.assertIn('>failed</span>', rows)     # collision_im3 failed
        self.assertIn('>skipped</span>', rows)    # rain not checked

    def test_no_players_no_section(self):
        for entries in (None, "not json", []):
            page = self.render(entries)
            self.assertNotIn('id="players"', page)
            self.assertNotIn("Recorded runs", page)


if __name__ == "__main__":
    unittest.main()
