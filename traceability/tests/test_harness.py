"""Self-test of the traceability harness against the fixture repository in fixtures/repo.

The fixture has one failing item (IM2), untested items (T1, R2 with code only; LC1 with only
a disabled test), items with nothing (GS1, A1, DD2, DC1), an orphan test label (R99) and an
orphan code tag (DD99). Run: /usr/bin/python3 -m unittest discover -s traceability/tests -t .
"""
import json
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

from traceability import analysis, build_report, evidence, vvdata

HERE = os.path.dirname(os.path.abspath(__file__))
FIX = os.path.join(HERE, "fixtures")
REPO = os.path.join(FIX, "repo")
SCRIPT = os.path.join(os.path.dirname(HERE), "build_report.py")
FIX_CONFIG = os.path.join(FIX, "config.yaml")
# The commit the fixture's verification results carry (data/peer_compare.json).
FIX_COMMIT = "f1x7f1x7f1x7f1x7f1x7f1x7f1x7f1x7f1x7f1x7"
HAVE_DOT = shutil.which("dot") is not None


def run_harness(repo, out, extra=()):
    argv = ["--source", repo, "--build", os.path.join(repo, "no-build"), "--out", out,
            "--results", os.path.join(repo, "results"), "--data", os.path.join(repo, "data"),
            "--no-run", "--no-checker", "--seed-tables", os.path.join(FIX, "seed_tables.yaml"),
            "--date", "2000-01-01 00:00 UTC", "--quiet", "--config", FIX_CONFIG,
            "--commit", FIX_COMMIT, *extra]
    return build_report.main(argv)


class FixtureReport(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="trace-selftest-")
        cls.out = os.path.join(cls.tmp, "reports")
        cls.exit_code = run_harness(REPO, cls.out)
        with open(os.path.join(cls.out, "traceability.json"), encoding="utf-8") as fh:
            cls.report = json.load(fh)
        cls.items = {i["label"]: i for i in cls.report["items"]}
        cls.tests = {t["id"]: t for t in cls.report["tests"]}

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def test_exit_code_is_nonzero_with_reasons(self):
        self.assertEqual(self.exit_code, 1)
        gate = self.report["gate"]
        self.assertFalse(gate["passed"])
        joined = " ".join(gate["reasons"])
        self.assertIn("model_tests:model/im2_spin", joined)
        for lab in ("T1", "DD2", "IM2", "R2"):
            self.assertIn(lab, joined)

    def test_missed_target_is_listed_not_failed(self):
        t = self.tests["peer_compare:speed_floor_2x_peer"]
        self.assertEqual(t["status"], "target-missed")
        self.assertEqual(t["target"], "fixture goal beyond the SRS")
        gate = self.report["gate"]
        self.assertEqual(gate["targets_missed"], ["peer_compare:speed_floor_2x_peer"])
        self.assertNotIn("peer_compare:speed_floor_2x_peer", gate["failing_tests"])
        self.assertEqual(self.report["summary"]["tests"]["verification"].get("target-missed"), 1)

    def test_a_should_requirement_is_a_goal_not_a_gate(self):
        t = self.tests["peer_compare:change_cost_within_10_percent"]
        self.assertEqual(t["status"], "goal-missed")
        self.assertEqual(t["figure"], "13.6 % > 10 %")
        gate = self.report["gate"]
        self.assertNotIn(t["id"], gate["failing_tests"])
        self.assertEqual(gate["goals_missed"], [t["id"]])
        self.assertEqual(gate["goals"], [{"label": "NFR2", "status": "goal missed",
                                          "checks": [t["id"]]}])
        self.assertNotIn("NFR2", " ".join(gate["reasons"]))
        self.assertEqual(self.items["NFR2"]["obligation"], "should")
        self.assertEqual(self.report["summary"]["tests"]["verification"].get("goal-missed"), 1)
        with open(os.path.join(self.out, "index.html"), encoding="utf-8") as fh:
            page = fh.read()
        self.assertIn('id="goals"', page)
        self.assertIn("13.6 % &gt; 10 %", page)

    def test_item_statuses(self):
        expected = {
            "IM1": "verified", "DD1": "verified", "R1": "verified", "NFR1": "verified",
            "NFR2": "goal missed",
            "IM2": "failing",
            "T1": "untested", "R2": "untested", "LC1": "untested",
            # Kinds only tests verify are "untested" without one, never "not implemented";
            # A1 is declared "assumed" in the fixture's config.yaml (no test can verify it).
            "GS1": "untested", "A1": "assumed", "DD2": "not implemented",
            "DC1": "untested",
        }
        self.assertEqual({k: v["status"] for k, v in self.items.items()}, expected)

    def test_totals_per_kind(self):
        by_kind = {row["kind"]: row for row in self.report["summary"]["by_kind"]}
        self.assertEqual(by_kind["IM"]["total"], 2)
        self.assertEqual(by_kind["IM"]["verified"], 1)
        self.assertEqual(by_kind["IM"]["failing"], 1)
        self.assertEqual(by_kind["IM"]["verified_percent"], 50.0)
        self.assertEqual(self.report["summary"]["by_status"],
                         {"verified": 4, "goal met": 0, "failing": 1, "goal missed": 1,
                          "model only": 0, "untested": 5, "assumed": 1, "not testable": 0,
                          "not implemented": 1})
        self.assertNotIn("GD", by_kind)  # general_definitions.yaml is an empty list

    def test_orphans_both_directions(self):
        orphans = self.report["orphans"]
        self.assertEqual([o["label"] for o in orphans["code_tags"]], ["DD99"])
        self.assertEqual(orphans["code_tags"][0]["file"], "src/solver.cpp")
        self.assertEqual(orphans["code_tags"][0]["line"], 3)
        self.assertEqual([o["label"] for o in orphans["test_labels"]], ["R99"])
        self.assertEqual(orphans["test_labels"][0]["tests"], ["model_tests:model/mystery"])
        # category labels are not orphans
        self.assertEqual({c["label"] for c in self.report["category_labels"]}, {"compile_fail", "traceability"})
        gaps = self.report["gaps"]
        self.assertEqual(gaps["no_code"], ["GS1", "A1", "DD2", "DC1", "R1", "NFR1", "NFR2", "LC1"])
        self.assertEqual(gaps["no_test"], ["GS1", "A1", "T1", "DD2", "DC1", "R2"])

    def test_code_sites(self):
        sites = {(s["label"], s["file"], s["line"]) for s in self.report["code_sites"]}
        self.assertIn(("DD1", "src/model/model.hpp", 2), sites)
        self.assertIn(("IM2", "src/model/model.hpp", 8), sites)
        self.assertIn(("T1", "src/model/model.hpp", 13), sites)  # inside a /** */ block
        self.assertNotIn("FAKE", {s["label"] for s in self.report["code_sites"]})

    def test_tests_and_oracles(self):
        t = self.tests["model_tests:model/im1_free_fall"]
        self.assertEqual(t["status"], "passed")
        self.assertEqual(t["labels"], ["IM1", "DD1"])
        self.assertEqual(t["file"], "tests/model/test_model.cpp")
        self.assertEqual(t["oracle"], "closed form x(t) = x0 + v0 t + g t^2 / 2 "
                                      "(exact for the symplectic Euler step at t = n dt).")
        spin = self.tests["model_tests:model/im2_spin"]
        self.assertEqual(spin["status"], "failed")
        self.assertEqual(spin["oracle"], "angular momentum is conserved without torque")
        self.assertIn("1 == 2", spin["details"])
        data = self.tests["model_tests:model/im1_samples"]
        self.assertEqual(data["status"], "passed")
        self.assertEqual(data["labels"], ["IM1"])
        self.assertEqual(data["samples"], "3 samples: 3 passed")
        self.assertEqual(data["oracle"], "three hand-computed trajectories")
        self.assertEqual(self.tests["model_tests:model/lc1_edge_edge"]["status"], "skipped")
        self.assertEqual(self.tests["ctest:cli_smoke"]["oracle"],
                         "the CLI exits 0 and prints the final state of a falling body")
        self.assertEqual(self.tests["peer_compare:step_time_within_2x_of_peer"]["labels"], ["NFR1"])
        self.assertEqual(self.tests["ctest:compile_fail.dd01_mass"]["oracle"],
                         "the seed's dimensionally wrong form of DD1 must not compile")
        self.assertIn("model_tests:model/mystery", self.report["missing_oracle"])
        self.assertNotIn("model_tests:model/im1_free_fall", self.report["missing_oracle"])
        self.assertTrue(any("@LC1" in x for x in self.report["registration"]))

    def test_oracle_kinds_and_weak_evidence(self):
        im1 = self.items["IM1"]
        self.assertIn("closed form", im1["oracle_kinds"])
        self.assertFalse(im1["weak_evidence"])
        # NFR1's only passing check compares with a peer engine: weak, and said so.
        nfr1 = self.items["NFR1"]
        self.assertEqual(nfr1["oracle_kinds"], ["peer"])
        self.assertTrue(nfr1["weak_evidence"])
        self.assertTrue(any(n.startswith("Weak evidence") for n in nfr1["notes"]))
        self.assertIn("NFR1", self.report["gaps"]["weak_evidence"])
        self.assertEqual(self.tests["model_tests:model/mystery"]["oracle_kinds"], ["unstated"])

    def test_declared_status_has_its_reason(self):
        a1 = self.items["A1"]
        self.assertEqual(a1["status"], "assumed")
        self.assertEqual(a1["status_reason"], "fixture: built into the types")
        self.assertIn("assumed: fixture: built into the types", a1["notes"])
        by_kind = {row["kind"]: row for row in self.report["summary"]["by_kind"]}
        self.assertEqual(by_kind["A"]["assumed"], 1)

    def test_item_evidence_lists(self):
        im1 = self.items["IM1"]
        self.assertEqual(im1["tests_passed"], 3)
        self.assertIn("peer_compare:trajectory_matches_closed_form", im1["tests"])
        self.assertTrue(any("no code carries" in n for n in self.items["R1"]["notes"]))
        self.assertTrue(any("verified only by tests" in n for n in self.items["GS1"]["notes"]))

    def test_matrices_and_seed_comparison(self):
        m = {x["id"]: x for x in self.report["matrices"]}
        self.assertEqual(m["table3"]["cells"]["R1"], ["IM1", "DC1"])
        self.assertEqual(m["table4"]["cells"]["IM1"], ["A1"])
        self.assertEqual(m["table5"]["cells"]["IM2"], ["T1"])
        self.assertIn("DD2", m["table5"]["empty_rows"])
        seed = {x["id"]: x for x in self.report["seed_tables"]}
        d3 = {(d["row"], d["column"], d["type"]) for d in seed["table3"]["differences"]}
        self.assertEqual(d3, {("GS1", "R1", "only in seed"),
                              ("R1", "Data Constraints", "only in data"),
                              ("R9", None, "row not in SRS data"),
                              ("R2", None, "row absent from seed")})
        d4 = {(d["row"], d["column"], d["type"]) for d in seed["table4"]["differences"]}
        self.assertEqual(d4, {("T??", None, "unresolved seed row"), ("IM2", "A1", "only in seed"),
                              ("DD2", None, "row absent from seed")})
        self.assertTrue(seed["table5"]["missing"])

    def test_errata_and_refby(self):
        self.assertEqual([e["id"] for e in self.report["errata"]], ["E1"])
        rb = {d["label"]: d for d in self.report["refby_disagreements"]}
        self.assertEqual(rb["DD1"]["only_in_seed"], ["IM2"])
        self.assertEqual(rb["A1"]["only_in_data"], ["LC1"])

    def test_outputs_written(self):
        html_path = os.path.join(self.out, "index.html")
        self.assertTrue(os.path.exists(html_path))
        with open(html_path, encoding="utf-8") as fh:
            page = fh.read()
        for needle in ('id="item-IM2"', "Gate: FAIL", 'id="orphan-tags"', "DD99", "R99",
                       'id="targets-missed"', "peer_compare:speed_floor_2x_peer",
                       "Seed Table 5 is missing", 'id="erratum-E1"', "peer_compare"):
            self.assertIn(needle, page)
        self.assertNotIn("<link ", page)  # self-contained: no external stylesheet
        self.assertTrue(os.path.exists(os.path.join(self.out, "traceability.md")))
        self.assertEqual(self.report["schema_version"], "1.6")
        self.assertTrue(os.path.exists(os.path.join(self.out, "plots", "peer_compare__Error_vs_step_size.svg")))
        self.assertEqual(self.report["coverage"]["totals"]["line_percent"], 80.0)
        if HAVE_DOT:
            for g in ("graph_table3", "graph_table4", "graph_table5", "graph_all"):
                self.assertTrue(os.path.exists(os.path.join(self.out, "graphs", g + ".svg")), g)
            self.assertIn("<svg", page)


class GreenFixture(unittest.TestCase):
    """A variant where every gated item passes: exit status 0."""

    def test_exit_zero_when_everything_gated_passes(self):
        tmp = tempfile.mkdtemp(prefix="trace-green-")
        try:
            repo = os.path.join(tmp, "repo")
            shutil.copytree(REPO, repo)
            junit = os.path.join(repo, "results", "boost", "model_tests.junit.xml")
            with open(junit, encoding="utf-8") as fh:
                text = fh.read()
            start = text.index("<failure")
            end = text.index("</system-err>", start) + len("</system-err>")
            with open(junit, "w", encoding="utf-8") as fh:
                fh.write(text[:start] + text[end:])
            for name, content in (("theoretical_models.yaml", "[]\n"),
                                  ("requirements.yaml", None), ("data_definitions.yaml", None)):
                path = os.path.join(repo, "srs", name)
                if content is not None:
                    with open(path, "w", encoding="utf-8") as fh:
                        fh.write(content)
                else:  # keep only the first item
                    with open(path, encoding="utf-8") as fh:
                        text = fh.read()
                    second = text.index("\n- label:")
                    with open(path, "w", encoding="utf-8") as fh:
                        fh.write(text[:second + 1])
            out = os.path.join(tmp, "reports")
            self.assertEqual(run_harness(repo, out), 0)
            with open(os.path.join(out, "traceability.json"), encoding="utf-8") as fh:
                rep = json.load(fh)
            self.assertTrue(rep["gate"]["passed"])
            self.assertEqual({i["label"]: i["status"] for i in rep["items"] if i["gated"]},
                             {"DD1": "verified", "IM1": "verified", "IM2": "verified", "R1": "verified"})
            # A missed target (a goal beyond the SRS) is listed but does not gate.
            self.assertEqual(rep["gate"]["targets_missed"], ["peer_compare:speed_floor_2x_peer"])
            with open(os.path.join(out, "index.html"), encoding="utf-8") as fh:
                page = fh.read()
            self.assertIn("Gate: PASS", page)
            self.assertNotIn("Gate: FAIL", page)
            self.assertIn('id="targets-missed"', page)
            # A missed goal (a "should" requirement) is shown on the first screen, not gating.
            self.assertEqual(rep["gate"]["goals_missed"],
                             ["peer_compare:change_cost_within_10_percent"])
            self.assertIn('id="goals"', page)
        finally:
            shutil.rmtree(tmp, ignore_errors=True)


class Provenance(unittest.TestCase):
    """Results of another commit or build, without provenance, or missing are refused."""

    def _run(self, edit_doc=None, build_prov=None, config_extra=""):
        tmp = tempfile.mkdtemp(prefix="trace-prov-")
        self.addCleanup(shutil.rmtree, tmp, True)
        repo = os.path.join(tmp, "repo")
        shutil.copytree(REPO, repo)
        path = os.path.join(repo, "data", "peer_compare.json")
        with open(path, encoding="utf-8") as fh:
            doc = json.load(fh)
        if edit_doc:
            edit_doc(doc)
        with open(path, "w", encoding="utf-8") as fh:
            json.dump(doc, fh)
        extra = []
        if build_prov is not None:
            os.makedirs(os.path.join(repo, "no-build"))
            with open(os.path.join(repo, "no-build", "provenance.json"), "w", encoding="utf-8") as fh:
                json.dump(build_prov, fh)
        if config_extra:
            cfg = os.path.join(tmp, "config.yaml")
            with open(FIX_CONFIG, encoding="utf-8") as fh:
                text = fh.read()
            with open(cfg, "w", encoding="utf-8") as fh:
                fh.write(text.replace("  - peer_compare\n", "  - peer_compare\n" + config_extra))
            extra = ["--config", cfg]
        out = os.path.join(tmp, "reports")
        code = run_harness(repo, out, extra)
        with open(os.path.join(out, "traceability.json"), encoding="utf-8") as fh:
            rep = json.load(fh)
        return code, rep, {t["id"]: t for t in rep["tests"]}, {i["label"]: i for i in rep["items"]}

    def test_matching_results_are_accepted(self):
        _, rep, tests, items = self._run(build_prov={"build_id": "fixturebuild0001"})
        self.assertEqual(tests["peer_compare:step_time_within_2x_of_peer"]["status"], "passed")
        self.assertNotIn("peer_compare:<provenance>", tests)
        self.assertEqual(rep["provenance"]["refused"], [])
        self.assertEqual(items["NFR1"]["status"], "verified")

    def test_another_commit_is_stale(self):
        def other_commit(doc):
            doc["provenance"]["commit"] = "0" * 40
        _, rep, tests, items = self._run(other_commit)
        t = tests["peer_compare:<provenance>"]
        self.assertEqual(t["status"], "error")
        self.assertIn("stale: results of commit 000000000000", t["details"])
        self.assertEqual(tests["peer_compare:step_time_within_2x_of_peer"]["status"], "error")
        self.assertEqual(items["NFR1"]["status"], "failing")
        self.assertIn("peer_compare:<provenance>", rep["gate"]["failing_tests"])

    def test_another_build_is_stale(self):
        _, _, tests, _ = self._run(build_prov={"build_id": "a-later-build"})
        self.assertIn("stale: results of build fixturebuild0001", tests["peer_compare:<provenance>"]["details"])

    def test_a_script_without_build_id_is_judged_by_its_commit(self):
        def no_build(doc):
            doc["provenance"]["build_id"] = None
        _, _, tests, _ = self._run(no_build, build_prov={"build_id": "a-later-build"})
        self.assertNotIn("peer_compare:<provenance>", tests)

    def test_results_without_provenance_are_refused(self):
        def strip(doc):
            del doc["provenance"]
        _, _, tests, _ = self._run(strip)
        self.assertIn("no provenance", tests["peer_compare:<provenance>"]["details"])

    def test_missing_expected_program_is_an_error(self):
        code, rep, tests, _ = self._run(config_extra="  - gsl_reference\n")
        t = tests["gsl_reference:<results file>"]
        self.assertEqual(t["status"], "error")
        self.assertIn("expected results missing", t["details"])
        self.assertEqual(rep["provenance"]["missing_programs"], ["gsl_reference"])
        self.assertEqual(code, 1)

    def test_absent_optional_program_is_named_not_run(self):
        extra = 'optional_programs:\n  fuzz: "scripts/fuzz.sh"\n  peer_compare: "its program"\n'
        code, rep, tests, _ = self._run(config_extra=extra)
        self.assertEqual(rep["provenance"]["not_run_programs"],
                         [{"program": "fuzz", "how": "scripts/fuzz.sh"}])
        self.assertNotIn("fuzz:<results file>", tests)
        self.assertEqual(rep["provenance"]["missing_programs"], [])


class ProcessExit(unittest.TestCase):
    def test_nonzero_exit_without_failing_case_is_an_error(self):
        tmp = tempfile.mkdtemp(prefix="trace-exit-")
        try:
            repo = os.path.join(tmp, "repo")
            shutil.copytree(REPO, repo)
            junit = os.path.join(repo, "results", "boost", "model_tests.junit.xml")
            with open(junit, encoding="utf-8") as fh:
                text = fh.read()
            start = text.index("<failure")
            end = text.index("</system-err>", start) + len("</system-err>")
            with open(junit, "w", encoding="utf-8") as fh:
                fh.write(text[:start] + text[end:])
            with open(os.path.join(repo, "results", "runs.json"), "w", encoding="utf-8") as fh:
                json.dump({"binaries": {"model_tests": {"run_exit": 134}}, "errors": [], "commands": []}, fh)
            out = os.path.join(tmp, "reports")
            self.assertEqual(run_harness(repo, out), 1)
            with open(os.path.join(out, "traceability.json"), encoding="utf-8") as fh:
                rep = json.load(fh)
            tests = {t["id"]: t for t in rep["tests"]}
            self.assertEqual(tests["model_tests:<process exit>"]["status"], "error")
            self.assertEqual({i["label"]: i["status"] for i in rep["items"]}["IM2"], "verified")
            self.assertIn("model_tests:<process exit>", rep["gate"]["failing_tests"])
        finally:
            shutil.rmtree(tmp, ignore_errors=True)


class ScriptEntryPoint(unittest.TestCase):
    def test_runs_as_a_script(self):
        tmp = tempfile.mkdtemp(prefix="trace-cli-")
        try:
            proc = subprocess.run(
                ["/usr/bin/python3", SCRIPT, "--source", REPO, "--out", tmp, "--no-run", "--no-checker",
                 "--results", os.path.join(REPO, "results"), "--data", os.path.join(REPO, "data"), "--quiet"],
                capture_output=True, text=True, timeout=300)
            self.assertEqual(proc.returncode, 1, proc.stderr)
            self.assertTrue(os.path.exists(os.path.join(tmp, "index.html")))
        finally:
            shutil.rmtree(tmp, ignore_errors=True)

    def test_missing_source_is_a_usage_error(self):
        self.assertEqual(build_report.main(["--source", "/nonexistent/dir", "--quiet"]), 2)


@unittest.skipUnless(shutil.which("ctest"), "ctest not installed")
class LiveRun(unittest.TestCase):
    """Run mode against a hand-written CTestTestfile.cmake: real ctest, a Boost entry whose
    binary was never built, one passing and one failing plain entry."""

    def test_run_mode_with_real_ctest(self):
        tmp = tempfile.mkdtemp(prefix="trace-live-")
        try:
            build = os.path.join(tmp, "build")
            os.makedirs(build)
            with open(os.path.join(build, "CTestTestfile.cmake"), "w", encoding="utf-8") as fh:
                fh.write('add_test(ghost@IM1 "%s" "--run_test=@IM1")\n'
                         'set_tests_properties(ghost@IM1 PROPERTIES LABELS "IM1")\n'
                         'add_test(cli_smoke "/bin/true")\n'
                         'set_tests_properties(cli_smoke PROPERTIES LABELS "R1")\n'
                         'add_test(bad_cli "/bin/false")\n'
                         'set_tests_properties(bad_cli PROPERTIES LABELS "R1")\n'
                         % os.path.join(build, "ghost"))
            out = os.path.join(tmp, "reports")
            code = build_report.main(["--source", REPO, "--build", build, "--out", out,
                                      "--data", os.path.join(REPO, "data"), "--no-checker", "--quiet",
                                      "--config", FIX_CONFIG, "--commit", FIX_COMMIT])
            self.assertEqual(code, 1)
            with open(os.path.join(out, "traceability.json"), encoding="utf-8") as fh:
                rep = json.load(fh)
            tests = {t["id"]: t for t in rep["tests"]}
            self.assertEqual(tests["ctest:cli_smoke"]["status"], "passed")
            self.assertEqual(tests["ctest:bad_cli"]["status"], "failed")
            self.assertEqual(tests["ghost@IM1"]["status"], "error")
            self.assertIn("not built", tests["ghost@IM1"]["details"])
            items = {i["label"]: i["status"] for i in rep["items"]}
            self.assertEqual(items["R1"], "failing")
            self.assertEqual(items["IM1"], "failing")  # the unbuilt binary is an error, not a pass
            self.assertTrue(rep["inputs"]["ran_tests"])
            self.assertTrue(os.path.exists(os.path.join(out, "raw", "runs.json")))
        finally:
            shutil.rmtree(tmp, ignore_errors=True)


HAVE_BUILD_TOOLS = all(shutil.which(t) for t in ("cmake", "ninja", "git", "c++"))
STAMP_SCRIPT = os.path.join(os.path.dirname(os.path.dirname(HERE)), "cmake", "TamiasProvenance.cmake")


@unittest.skipUnless(HAVE_BUILD_TOOLS, "needs cmake, ninja, git and a C++ compiler")
class BuildBinding(unittest.TestCase):
    """The DD17 experiment: a sign flipped in a source after the build, not rebuilt, reported
    from the existing results: the gate fails, naming the stale build and the changed file.
    A one-file CMake project in a fresh git repository stands for the project's build (the
    same stamp script, run as its last step)."""

    def setUp(self):
        self.tmp = tempfile.mkdtemp(prefix="trace-build-")
        self.addCleanup(shutil.rmtree, self.tmp, True)
        self.repo = os.path.join(self.tmp, "repo")
        shutil.copytree(REPO, self.repo)
        # The fixture's coverage names no build: measured for another tree, refused apart.
        os.remove(os.path.join(self.repo, "data", "coverage.json"))
        with open(os.path.join(self.repo, "damping.cpp"), "w", encoding="utf-8") as fh:
            fh.write("double damping(double c, double v) { return -(c * v); }\n"
                     "int main() { return damping(1.0, 1.0) < 0.0 ? 0 : 1; }\n")
        with open(os.path.join(self.repo, "CMakeLists.txt"), "w", encoding="utf-8") as fh:
            fh.write("cmake_minimum_required(VERSION 3.25)\nproject(mini CXX)\n"
                     "add_executable(damping damping.cpp)\n"
                     "add_custom_target(stamp ALL COMMAND ${CMAKE_COMMAND} "
                     "-DSOURCE_DIR=${CMAKE_SOURCE_DIR} -DOUT_DIR=${CMAKE_BINARY_DIR} "
                     "-DCOMPILER=c++ -DFLAGS=-O2 -DOPTIONS=none -DPACKAGES=cmake "
                     f"-P {STAMP_SCRIPT} VERBATIM)\nadd_dependencies(stamp damping)\n")
        git = ["git", "-C", self.repo, "-c", "user.name=t", "-c", "user.email=t@t"]
        subprocess.run(git[:3] + ["init", "-q"], check=True)
        subprocess.run(git + ["add", "-A"], check=True)
        subprocess.run(git + ["commit", "-qm", "fixture"], check=True)
        self.build = os.path.join(self.tmp, "build")
        subprocess.run(["cmake", "-S", self.repo, "-B", self.build, "-G", "Ninja"], check=True,
                       capture_output=True)
        subprocess.run(["cmake", "--build", self.build], check=True, capture_output=True)

    def report(self):
        out = os.path.join(self.tmp, "reports")
        code = build_report.main(["--source", self.repo, "--build", self.build, "--out", out,
                                  "--results", os.path.join(self.repo, "results"),
                                  "--data", os.path.join(self.repo, "data"), "--no-run",
                                  "--no-checker", "--quiet", "--config", FIX_CONFIG])
        with open(os.path.join(out, "traceability.json"), encoding="utf-8") as fh:
            return code, json.load(fh)

    def test_coverage_of_another_tree_is_refused(self):
        with open(os.path.join(REPO, "data", "coverage.json"), encoding="utf-8") as fh:
            cov = json.load(fh)
        cov["provenance"] = {"commit": "x", "tree": "0" * 40}
        with open(os.path.join(self.repo, "data", "coverage.json"), "w", encoding="utf-8") as fh:
            json.dump(cov, fh)
        _, rep = self.report()
        self.assertTrue(any("coverage" in p and "000000000000" in p
                            for p in rep["provenance"]["build_problems"]))

    def test_a_build_of_the_checkout_is_accepted(self):
        _, rep = self.report()
        self.assertEqual(rep["provenance"]["build_problems"], [])
        self.assertEqual(rep["builds"][0]["tree"], rep["provenance"]["source_tree"])

    def test_a_flipped_sign_not_rebuilt_fails_the_gate(self):
        path = os.path.join(self.repo, "damping.cpp")
        with open(path, encoding="utf-8") as fh:
            text = fh.read()
        with open(path, "w", encoding="utf-8") as fh:
            fh.write(text.replace("return -(c * v);", "return c * v;"))
        code, rep = self.report()
        self.assertEqual(code, 1)
        problems = rep["provenance"]["build_problems"]
        self.assertTrue(any("stale" in p and "damping.cpp" in p for p in problems), problems)
        self.assertTrue(any("ninja -n" in p for p in problems), problems)
        self.assertIn("build:<up to date>", rep["gate"]["failing_tests"])

    def test_a_target_rebuilt_alone_and_the_source_restored_is_still_stale(self):
        path = os.path.join(self.repo, "damping.cpp")
        with open(path, encoding="utf-8") as fh:
            text = fh.read()
        with open(path, "w", encoding="utf-8") as fh:
            fh.write(text.replace("return -(c * v);", "return c * v;"))
        subprocess.run(["cmake", "--build", self.build, "--target", "damping"], check=True,
                       capture_output=True)
        with open(path, "w", encoding="utf-8") as fh:
            fh.write(text)
        _, rep = self.report()
        problems = rep["provenance"]["build_problems"]
        # The tree is the stamped one again; only the build system knows the object is not.
        self.assertEqual(len(problems), 1, problems)
        self.assertIn("ninja -n", problems[0])


class Units(unittest.TestCase):
    def test_status_rules(self):
        p = {"status": "passed"}
        f = {"status": "failed"}
        s = {"status": "skipped"}
        self.assertEqual(analysis.item_status([], [p]), "verified")
        self.assertEqual(analysis.item_status([1], [p, f]), "failing")
        self.assertEqual(analysis.item_status([1], []), "untested")
        self.assertEqual(analysis.item_status([], [s]), "untested")
        self.assertEqual(analysis.item_status([], []), "not implemented")
        self.assertEqual(analysis.item_status([], [], "A"), "untested")

    def test_declared_statuses(self):
        # Oracle: the rule stated in docs/traceability.md: a declared status stands only while
        # no labelled test exists; tests decide otherwise.
        p = {"status": "passed"}
        self.assertEqual(analysis.item_status([], [], "A", "assumed"), "assumed")
        self.assertEqual(analysis.item_status([], [], "UC", "not testable"), "not testable")
        self.assertEqual(analysis.item_status([], [p], "A", "assumed"), "verified")
        warnings = []
        got = analysis.declared_statuses(
            {"without_tests": {"A1": {"status": "assumed", "reason": "r"},
                               "A9": {"status": "assumed", "reason": "r"},
                               "UC1": {"status": "untested", "reason": "r"},
                               "UC3": {"status": "verified", "reason": "r"},
                               "UC2": {"status": "not testable"}}}, {"A1", "UC1", "UC2", "UC3"},
            warnings)
        # "untested" may carry its reason (a test not yet run); a status no test gave may not.
        self.assertEqual(got, {"A1": {"status": "assumed", "reason": "r"},
                               "UC1": {"status": "untested", "reason": "r"}})
        self.assertEqual(len(warnings), 3)
        self.assertEqual(analysis.item_status([], [], "NFR", "untested"), "untested")

    def test_link_grades(self):
        # Oracle: the rules stated in traceability/links.py's docstring, case by case.
        from traceability import links
        r1, dd8 = {"kind": "R"}, {"kind": "DD"}
        model = {"origin": "boost", "file": "tests/model/test_dd08.cpp", "oracle": "closed form",
                 "oracle_kinds": ["closed form"]}
        world = dict(model, file="tests/system/test_collisions.cpp")
        golden = dict(world, oracle="golden hashes", oracle_kinds=["regression"])
        peer = dict(world, oracle="Chipmunk 7", oracle_kinds=["peer"])
        mute = dict(world, oracle=None, oracle_kinds=["unstated"])
        cli = {"origin": "ctest", "file": "apps/cli/CMakeLists.txt", "labels": ["R1"],
               "oracle": "the scene's bodies, a hand count", "oracle_kinds": ["stated rule"]}
        self.assertEqual(links.grade(dd8, model)[0], "strong")
        self.assertEqual(links.grade(r1, world)[0], "strong")
        grade, reasons, facts = links.grade(r1, model)
        self.assertEqual((grade, facts["level"]), ("weak", "model"))
        self.assertIn("model alone", reasons[0])
        self.assertEqual(links.grade(dd8, golden)[0], "weak")
        self.assertEqual(links.grade(dd8, peer)[0], "weak")
        self.assertEqual(links.grade({"kind": "NFR"}, peer, peer_reference=True)[0], "strong")
        self.assertEqual(links.grade(dd8, mute)[1], ["states no oracle"])
        self.assertEqual(links.level_of(cli), "command")
        pool = [{"item": f"DD{i}", "test": f"t{i}"} for i in range(100)]
        first = links.sample(pool, 30, "abc")
        self.assertEqual(first, links.sample(list(reversed(pool)), 30, "abc"))
        self.assertNotEqual(first, links.sample(pool, 30, "abd"))
        # A link's draw does not depend on the others: drop one unsampled link, same sample.
        rest = [ln for ln in pool if ln not in first]
        self.assertEqual(first, links.sample(first + rest[1:], 30, "abc"))

    def test_model_only_items(self):
        # Oracle: the rule stated in docs/traceability.md ("model only"): an item marked
        # engine: model-only in srs/ (the fixture's T1, marked here) is verified only by its
        # module's tests; a passing engine test makes it neither verified nor model only, and
        # its link is weak with the reason; an item the engine evaluates (DD1) is verified by
        # the same kind of test.
        from traceability import srsdata
        srs = srsdata.load_srs(os.path.join(REPO, "srs"))
        srs.items["T1"].update(engine="model-only", engine_reason="Not in the engine.")
        engine = {"origin": "boost", "file": "tests/engine/test_motion.cpp", "status": "passed",
                  "oracle": "closed form F = m a"}
        model = dict(engine, file="tests/model/test_t1.cpp")

        def t1_and_dd1(tests):
            res = analysis.analyse(srs, [], [dict(t) for t in tests], {"category_labels": []})
            return {i["label"]: i for i in res["items"] if i["label"] in ("T1", "DD1")}

        got = t1_and_dd1([dict(engine, id="e", labels=["T1", "DD1"])])
        self.assertEqual(got["T1"]["status"], "untested")
        self.assertEqual(got["DD1"]["status"], "verified")
        self.assertEqual(got["T1"]["links"]["e"]["grade"], "weak")
        self.assertIn("engine: model-only", " ".join(got["T1"]["links"]["e"]["reasons"]))
        self.assertEqual(got["DD1"]["links"]["e"]["grade"], "strong")
        self.assertEqual((got["T1"]["engine"], got["DD1"]["engine"]), ("model only", "engine"))
        got = t1_and_dd1([dict(engine, id="e", labels=["T1"]), dict(model, id="m", labels=["T1"])])
        self.assertEqual(got["T1"]["status"], "model only")
        self.assertEqual(got["T1"]["status_reason"], "Not in the engine.")
        self.assertFalse(got["T1"]["weak_evidence"])
        self.assertTrue(any(n.startswith("Model only") for n in got["T1"]["notes"]))
        got = t1_and_dd1([dict(engine, id="e", labels=["T1"], status="failed"),
                          dict(model, id="m", labels=["T1"])])
        self.assertEqual(got["T1"]["status"], "failing")
        # A property (engine: property) is a law the engine's results obey: engine tests count.
        srs.items["T1"].update(engine="property", engine_reason="A law the results obey.")
        got = t1_and_dd1([dict(engine, id="e", labels=["T1"])])
        self.assertEqual((got["T1"]["status"], got["T1"]["engine"]), ("verified", "property"))
        self.assertEqual(got["T1"]["links"]["e"]["grade"], "strong")
        self.assertTrue(any(n.startswith("A property") for n in got["T1"]["notes"]))

    def test_labelled_test_without_oracle_is_weak_evidence(self):
        # Oracle: the rule stated in docs/traceability.md: an SRS-labelled test that states no
        # oracle is listed, and flagged on its item, even beside strong evidence.
        from traceability import srsdata
        srs = srsdata.load_srs(os.path.join(REPO, "srs"))
        tests = [{"id": "a", "labels": ["IM1"], "status": "passed", "origin": "boost",
                  "oracle": "closed form x(t) = x0 + v0 t"},
                 {"id": "b", "labels": ["IM1"], "status": "passed", "origin": "boost", "oracle": None},
                 {"id": "c", "labels": ["R99"], "status": "passed", "origin": "boost", "oracle": None}]
        res = analysis.analyse(srs, [], tests, {"category_labels": []})
        im1 = next(i for i in res["items"] if i["label"] == "IM1")
        self.assertEqual(im1["tests_without_oracle"], ["b"])
        self.assertFalse(im1["weak_evidence"])  # not verified by weak evidence only
        self.assertTrue(any(n.startswith("Weak evidence: 1 labelled test(s) state no oracle")
                            for n in im1["notes"]))
        self.assertEqual(res["gaps"]["unstated_oracle"], ["IM1"])
        self.assertEqual(res["missing_oracle_srs"], ["b"])  # c names no SRS item
        self.assertEqual(res["missing_oracle"], ["b", "c"])

    def test_peer_as_the_items_own_reference(self):
        # Oracle: the rule stated in docs/traceability.md: a peer oracle is weak evidence except
        # for an item declared in peer_is_the_reference.
        from traceability import srsdata
        srs = srsdata.load_srs(os.path.join(REPO, "srs"))
        tests = [{"id": "p", "labels": ["NFR1"], "status": "passed", "origin": "verification",
                  "oracle": "Chipmunk 7 on the identical scene, thread CPU time"}]
        plain = analysis.analyse(srs, [], [dict(t) for t in tests], {"category_labels": []})
        self.assertTrue(next(i for i in plain["items"] if i["label"] == "NFR1")["weak_evidence"])
        cfg = {"category_labels": [], "peer_is_the_reference": {"NFR1": "a time ratio"}}
        res = analysis.analyse(srs, [], [dict(t) for t in tests], cfg)
        nfr1 = next(i for i in res["items"] if i["label"] == "NFR1")
        self.assertFalse(nfr1["weak_evidence"])
        self.assertIn("own reference, not weak evidence: a time ratio", " ".join(nfr1["notes"]))

    def test_oracle_kinds(self):
        # Oracle: hand-classified oracle statements of this repository's tests.
        k = analysis.oracle_kinds
        self.assertEqual(k("IM3's closed form, evaluated here from the SRS text"), ["closed form"])
        self.assertEqual(k("GSL rk8pd at tolerance 1e-12"), ["GSL reference"])
        self.assertEqual(k("GD1 (conservation of momentum, from T2)"), ["conservation law"])
        self.assertEqual(k("energy never rising beyond the soft contact's bound"), ["property"])
        self.assertEqual(k("Chipmunk 7.0.3 on the same scene"), ["peer"])
        self.assertEqual(k("the committed value, produced by another build (golden hashes)"),
                         ["regression"])
        self.assertEqual(k("SRS Table 1, row C_R: 0 <= C_R <= 1"), ["stated rule"])
        self.assertEqual(k("DCX_dt (srs/data_constraints.yaml): the time step is > 0"),
                         ["stated rule"])
        self.assertEqual(k("statics: the joint must balance its weight"), ["closed form"])
        self.assertEqual(k("the CLI exits 0"), ["other"])
        self.assertEqual(k(None), ["unstated"])
        self.assertEqual(k("closed form; momentum conserved"), ["closed form", "conservation law"])
        # A golden-section search finds a minimum; it is no golden value.
        self.assertEqual(k("the entry is its first root (golden-section search, bisection)"),
                         ["other"])
        # Conservative advancement conserves nothing.
        self.assertEqual(k("the property of DD29's conservative advancement"), ["property"])
        self.assertEqual(k("query_oracle.hpp, an independent implementation of the gaps"),
                         ["independent implementation"])

    def test_a_case_without_assertions_is_no_evidence(self):
        # Oracle: Boost.Test's JUnit count: a case that passed after zero assertions is an
        # error (it checked nothing); one with assertions stays passed.
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "cases.xml")
            with open(path, "w", encoding="utf-8") as fh:
                fh.write('<testsuite><testcase assertions="0" classname="s" name="empty"/>'
                         '<testcase assertions="2" classname="s" name="real"/></testsuite>')
            r = evidence.parse_junit(path)
        self.assertEqual(r[("s", "empty")]["status"], "error")
        self.assertIn("verifies nothing", r[("s", "empty")]["message"])
        self.assertEqual(r[("s", "real")]["status"], "passed")

    def test_comment_spans(self):
        spans, inb = evidence._comment_spans('x = "\\srs{A}"; // \\srs{B}', False, False)
        self.assertEqual(len(spans), 1)
        self.assertFalse(inb)
        spans, inb = evidence._comment_spans("int a; /* start", False, False)
        self.assertTrue(inb)
        spans, inb = evidence._comment_spans(" * \\srs{C} */ int b;", True, False)
        self.assertEqual(spans[0][0], 0)
        self.assertFalse(inb)
        spans, _ = evidence._comment_spans('s = "#x"  # \\srs{D}', False, True)
        self.assertEqual(len(spans), 1)

    def test_nested_suites_inherit_labels(self):
        dot = "\n".join([
            'digraph G {rankdir=LR;',
            'tu1[shape=ellipse,peripheries=2,fontname=Helvetica,color=green,label="m"];',
            '{',
            'tu2[shape=Mrecord,fontname=Helvetica,color=green,label="outer|a.cpp(3)|labels: @R1"];',
            'tu1 -> tu2;',
            '{',
            'tu3[shape=Mrecord,fontname=Helvetica,color=yellow,label="inner|a.cpp(4)"];',
            'tu2 -> tu3;',
            '{',
            'tu65536[shape=Mrecord,fontname=Helvetica,color=green,label="c|a.cpp(5)|labels: @IM3"];',
            'tu3 -> tu65536;',
            '}', '}',
            'tu65537[shape=Mrecord,fontname=Helvetica,color=green,label="tmpl<int>|a.cpp(9)"];',
            'tu1 -> tu65537;',
            '}', '}'])
        cases = evidence.boost_cases(dot)
        self.assertEqual([c["path"] for c in cases], [["outer", "inner", "c"], ["tmpl<int>"]])
        self.assertEqual(cases[0]["labels"], ["IM3", "R1"])
        self.assertFalse(cases[0]["enabled"])  # its suite is disabled
        self.assertEqual(cases[1]["labels"], [])

    def test_oracle_block_forms(self):
        lines = ["// Something else", "// Oracle: a = b", "//   continued", "BOOST_AUTO_TEST_CASE(x) {}",
                 "", "/* Oracle: c */", "BOOST_TEST_DECORATOR(*utf::label(\"R1\"))",
                 "BOOST_DATA_TEST_CASE(y, data) {}", "", "BOOST_AUTO_TEST_CASE(z) {}"]
        ora = [evidence._oracle_from_block(evidence._comment_block_above(lines, i)) for i in (3, 7, 9)]
        self.assertEqual(ora, ["a = b continued", "c", None])

    def test_checker_agreement(self):
        own = [{"label": "DD1"}, {"label": "T4"}]
        self.assertTrue(build_report.compare_checker(own, [{"label": "T4"}, {"label": "DD1"}])["agrees"])
        ag = build_report.compare_checker(own, [{"label": "T4"}, {"label": "GD1"}])
        self.assertEqual((ag["only_checker"], ag["only_harness"]), (["GD1"], ["DD1"]))
        self.assertIsNone(build_report.compare_checker(own, None))

    def test_verification_schema_validation(self):
        self.assertEqual(vvdata.validate({"program": "p", "checks": [], "tables": [], "series": []}), [])
        errs = vvdata.validate({"checks": [{"name": "c", "passed": "yes"}],
                                "series": [{"lines": [{"x": [1, 2], "y": [1]}]}]})
        self.assertEqual(len(errs), 3)


if __name__ == "__main__":
    unittest.main()
