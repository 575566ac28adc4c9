"""The formula lint's own test: each rule flags its formula written outside model/, and
nothing in a comment, a string, model/ or the rule's allowed file; KNOWN entries that stopped
matching fail. Oracle: hand-written C++ fragments, one per rule, with the verdict stated."""
import os
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import formula_lint as fl  # noqa: E402

# One fragment per rule, each the formula as an engine file might write it again.
SAMPLES = {
    "cross_2d": "double cross(Vec2d a, Vec2d b) { return a.x * b.y - a.y * b.x; }",
    "gd2_g": "Vec2d g{0.0, -9.81};",
    "t5_disc": "return dot(d, d) <= c.radius * c.radius;",
    "t5_polygon": "for (int i = 0; i < n; ++i)\n    if (dot(p.normals[i], q - p.vertices[i]) > 0.0)\n"
                  "        return false;",
    "im4_overlap": "return a.min_x < b.max_x && a.max_x > b.min_x;",
    "im7_softness": "const double a1 = 2.0 * damping_ratio + h * omega;",
    "im1_im2_halves": "sb.dp += sb.v * h;",
    "im3_apply": "b.w -= b.inv_I * (lambda * arm);",
    "dd08_reach": "const double j = -(vn - target) * normal_mass;",
    "dd12_bounce": "const double t = -restitution * vn;",
    "dd15_energy": "e += 0.5 * mass * dot(v, v);",
}


class FormulaLint(unittest.TestCase):
    def test_every_rule_has_a_sample(self):
        self.assertEqual(sorted(SAMPLES), sorted(r.name for r in fl.RULES))

    def test_each_sample_is_flagged_by_its_rule(self):
        for name, code in SAMPLES.items():
            with self.subTest(rule=name):
                found = fl.scan_text("src/tamias2d/dynamics/x.cpp", code)
                self.assertIn(name, [f[0] for f in found])

    def test_line_numbers(self):
        found = fl.scan_text("src/x.cpp", "int a;\n\n" + SAMPLES["t5_polygon"])
        self.assertEqual([(f[0], f[2]) for f in found], [("t5_polygon", 4)])

    def test_comments_strings_and_model_are_not_read(self):
        for name, code in SAMPLES.items():
            with self.subTest(rule=name):
                commented = "\n".join("// " + line for line in code.splitlines())
                self.assertEqual(fl.scan_text("src/x.cpp", commented), [])
                self.assertEqual(fl.scan_text("src/x.cpp", "/* " + code + " */"), [])
                self.assertEqual(fl.scan_text("src/tamias2d/model/x.hpp", code), [])
        self.assertEqual(fl.scan_text("src/x.cpp", 'const char* s = "9.81";'), [])

    def test_allowed_file(self):
        self.assertEqual(fl.scan_text("include/tamias2d/vec2.hpp", SAMPLES["cross_2d"]), [])
        self.assertEqual(fl.scan_text("include/tamias2d/world_def.hpp", SAMPLES["gd2_g"]), [])
        self.assertTrue(fl.scan_text("include/tamias2d/world.hpp", SAMPLES["gd2_g"]))

    def test_calls_into_the_model_pass(self):
        code = ("sb.dp = bridge::position_half(sb.dp, sb.v, h);\n"
                "return model::t5::contains(c.center, c.radius, local);\n"
                "const double g = 19.81 + x9.81;\n")
        self.assertEqual(fl.scan_text("src/tamias2d/dynamics/x.cpp", code), [])

    def test_known_and_stale(self):
        known = {("cross_2d", "src/a.cpp"): "waiting", ("gd2_g", "src/b.cpp"): "fixed"}
        findings = fl.scan_text("src/a.cpp", SAMPLES["cross_2d"]) + \
            fl.scan_text("src/c.cpp", SAMPLES["dd12_bounce"])
        new, old, stale = fl.judge(findings, known)
        self.assertEqual([(f[0], f[1]) for f in new], [("dd12_bounce", "src/c.cpp")])
        self.assertEqual([(f[0], f[1]) for f in old], [("cross_2d", "src/a.cpp")])
        self.assertEqual(stale, [("gd2_g", "src/b.cpp")])

    def test_tree_exit_status(self):
        with tempfile.TemporaryDirectory() as root:
            os.makedirs(os.path.join(root, "src/tamias2d/model"))
            with open(os.path.join(root, "src/tamias2d/model/m.hpp"), "w") as f:
                f.write(SAMPLES["dd15_energy"])
            saved = dict(fl.KNOWN)
            try:
                # A KNOWN entry absent from this tree is stale, so the run fails...
                fl.KNOWN.clear()
                fl.KNOWN[("cross_2d", "src/a.cpp")] = "waiting"
                self.assertEqual(fl.main(["--root", root]), 1)
                fl.KNOWN.clear()
                self.assertEqual(fl.main(["--root", root]), 0)  # ...and passes without it
                with open(os.path.join(root, "src/e.cpp"), "w") as f:
                    f.write(SAMPLES["dd15_energy"])
                self.assertEqual(fl.main(["--root", root]), 1)
            finally:
                fl.KNOWN.update(saved)


if __name__ == "__main__":
    unittest.main()
