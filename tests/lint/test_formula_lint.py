"""The formula lint's own test: each rule flags its formula written outside model/, and
nothing in a comment, a string, model/ or the rule's allowed file; KNOWN entries that stopped
matching fail. Oracle: hand-written C++ fragments, one per rule, with the verdict stated."""
import os
import shutil
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
    "dd08_reach": "const double j = -(vn - target) * normal_mass;",
    "dd12_bounce": "const double t = -restitution * vn;",
    "dd15_energy": "e += 0.5 * mass * dot(v, v);",
    "im3_jumps": "A.omega -= a.inv_I * lambda;",
    "dd17_dd18_damping": "return -(c_v * v);",
    "im5_decay_rate": "return 1.0 / (1.0 + c * h);",
    "dd29_motion_bound": "fast = std::sqrt(dp2) + std::abs(sb.dq) * reach > seen;",
    "dd29_sweep": "b.w = f.w0 + t * (b.w - f.w0);",
    "dcx_shape_area": "const double m = density * 0.5 * cross(a, b);",
    "im7_target": "const V speculative_target = -s * broadcast<V>(st.inv_h);",
    "im7_two_point": "const auto first_active = both(only1 >= zero, k12 * only1 + b2 >= zero);",
    "im6_bias": "rhs += rigid.bias_rate * l.perpendicular;",
    "im6_reaction": "return reaction_impulse(j) * inv_h;",
    "im6_im7_soft_impulse": "return -(mass_scale * solved) - impulse_scale * accumulated;",
    "dd26_correction_rate": "const double rate = j.correction_factor / h;",
    "joint_impulse_bound": "j.linear_impulse = bridge::clamp_impulse(old + P, j.max_force * h);",
}

# The duplicates an audit found, as they were written before each was folded into its module:
# (rule, file it stood in, its text). Put back into a scratch copy of the tree, each must be
# flagged in that file.
DUPLICATES = [
    ("im5_decay_rate", "src/tamias2d/model/im5_motion_with_damping.hpp",
     "inline Dimensionless decay_factor(Rate c, Time h) {\n    return 1.0 / (1.0 + c * h);\n}"),
    ("dd29_motion_bound", "src/tamias2d/dynamics/step_solver.cpp",
     "fast = std::sqrt(dp2) + std::abs(sb.dq) * reach > seen;"),
    ("dd29_sweep", "src/tamias2d/dynamics/continuous.cpp",
     "b.center = f.c0 + t * (sweep.c1 - sweep.c0);\n    b.v = f.v0 + t * (b.v - f.v0);"),
    ("dd29_sweep", "src/tamias2d/collision/time_of_impact.hpp",
     "xf.q = Rot::from_angle(a0 + t * (a1 - a0));\n"
     "xf.p = c0 + t * (c1 - c0) - rotate(xf.q, local_center);"),
    ("dcx_shape_area", "src/tamias2d/geometry/mass_properties.cpp",
     "twice += cross(p.vertices[i] - p.vertices[0], p.vertices[i + 1] - p.vertices[0]);"),
    ("dcx_shape_area", "src/tamias2d/geometry/mass_properties.cpp",
     "const double m = weight * 0.5 * cross(e1, e2);"),
    ("dcx_shape_area", "src/tamias2d/geometry/shape_factory.cpp",
     "twice_area += cross(hull[i] - hull[0], hull[(i + 1) % n] - hull[0]);"),
    ("dcx_shape_area", "src/tamias2d/validation.cpp",
     "twice_area += cross(p.vertices[i] - p.vertices[0], p.vertices[(i + 1) % n] - "
     "p.vertices[0]);"),
    ("im3_jumps", "src/tamias2d/model/dd19_point_constraint.hpp",
     "A.v -= a.inv_m * P;\n    A.omega -= a.inv_I * per_radian(cross(r_A, P));\n"
     "    B.v += b.inv_m * P;\n    B.omega += b.inv_I * per_radian(cross(r_B, P));"),
    ("im3_jumps", "src/tamias2d/model/dd22_angular_constraint.hpp",
     "A.omega -= a.inv_I * lambda;\n    B.omega += b.inv_I * lambda;"),
    ("im7_target", "src/tamias2d/dynamics/contacts/contact_iteration.hpp",
     "const V speculative_target = -s * broadcast<V>(st.inv_h);"),
    ("im7_target", "src/tamias2d/dynamics/contacts/contact_iteration.hpp",
     "const V bias =\n"
     "    max(broadcast<V>(st.softness.bias_rate) * min(s + broadcast<V>(st.linear_slop), zero),\n"
     "        -broadcast<V>(st.push_max_velocity));"),
    ("im7_target", "src/tamias2d/dynamics/joints/joint_solver.hpp",
     "if (c > 0.0)\n    return {c / h, 1.0, 0.0};"),
    ("im6_bias", "src/tamias2d/dynamics/joints/joint_solver.hpp",
     "return {softness.bias_rate * c, softness.mass_scale, softness.impulse_scale};"),
    ("im7_two_point", "src/tamias2d/dynamics/contacts/contact_iteration.hpp",
     "const V b1 = vn1 - t1 - (c.k11 * x1 + c.k12 * x2);"),
    ("im7_two_point", "src/tamias2d/dynamics/two_point_lcp.hpp",
     "const V both1 = -(inv11 * b1 + inv12 * b2);\n"
     "const auto first_active = both(only1 >= zero, k12 * only1 + b2 >= zero);"),
    ("im6_bias", "src/tamias2d/dynamics/joints/weld_joint.cpp",
     "rhs += s.bias_rate * current_joint_angle(j, a, b);"),
    ("im6_bias", "src/tamias2d/dynamics/joints/wheel_joint.cpp",
     "rhs += rigid.bias_rate * l.perpendicular;"),
    ("im6_bias", "src/tamias2d/dynamics/joints/motor_joint.cpp",
     "const double rhs_angle = bridge::joint_speed(a, b) + rate * current_joint_angle(j, a, b);"),
    ("im6_bias", "src/tamias2d/dynamics/joints/revolute_joint.cpp",
     "bridge::joint_speed(a, b) + soft.bias_rate * current_joint_angle(j, a, b);"),
    ("dd26_correction_rate", "src/tamias2d/dynamics/joints/motor_joint.cpp",
     "const double rate = j.correction_factor / h;"),
    ("joint_impulse_bound", "src/tamias2d/dynamics/joints/joint_solver.cpp",
     "bridge::clamp_angular_impulse(j.motor_impulse + lambda, j.max_motor * h);"),
    ("joint_impulse_bound", "src/tamias2d/dynamics/joints/target_joint.cpp",
     "j.linear_impulse = bridge::clamp_impulse(old + P, j.max_force * h);"),
    ("joint_impulse_bound", "src/tamias2d/dynamics/joints/motor_joint.cpp",
     "bridge::clamp_angular_impulse(j.angular_impulse + lambda, j.max_torque * h);"),
    ("joint_impulse_bound", "src/tamias2d/dynamics/joints/prismatic_joint.cpp",
     "bridge::clamp_axial_impulse(j.motor_impulse + lambda, j.max_motor * h);"),
    ("im6_im7_soft_impulse", "src/tamias2d/model/dd19_point_constraint.hpp",
     "return -(mass_scale * solved) - impulse_scale * accumulated;"),
    ("im6_im7_soft_impulse", "src/tamias2d/model/dd20_distance_constraint.hpp",
     "return -(mass_scale * (rhs / K)) - impulse_scale * accumulated;"),
    ("im6_im7_soft_impulse", "src/tamias2d/model/dd23_line_constraint.hpp",
     "return {-(mass_scale * linear) - impulse_scale * accumulated.linear,\n"
     "        -(mass_scale * angular) - impulse_scale * accumulated.angular};"),
    ("im6_reaction", "src/tamias2d/world.cpp",
     "return reaction_impulse(impl_->joints.get(id)) * impl_->inv_h;"),
]


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
        for r in fl.RULES:
            if not (r.home or r.everywhere):
                self.assertEqual(fl.scan_text("src/tamias2d/model/x.hpp", SAMPLES[r.name]), [])
        self.assertEqual(fl.scan_text("src/x.cpp", 'const char* s = "9.81";'), [])

    def test_a_home_holds_its_formula_and_other_modules_may_not(self):
        homed = [r for r in fl.RULES if r.home or r.everywhere]
        self.assertGreaterEqual(len(homed), 10)
        for r in homed:
            with self.subTest(rule=r.name):
                found = fl.scan_text("src/tamias2d/model/other.hpp", SAMPLES[r.name])
                self.assertIn(r.name, [f[0] for f in found])
                for home in r.home:
                    self.assertTrue(home.startswith(fl.MODEL_DIR), home)
                    self.assertNotIn(r.name, [f[0] for f in fl.scan_text(home, SAMPLES[r.name])])

    def test_each_folded_duplicate_put_back_is_flagged(self):
        root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
        with tempfile.TemporaryDirectory() as scratch:
            for top in fl.SCANNED:
                if os.path.isdir(os.path.join(root, top)):
                    shutil.copytree(os.path.join(root, top), os.path.join(scratch, top))
            before = {(f[0], f[1]) for f in fl.scan_tree(scratch)}
            for rule, path, text in DUPLICATES:
                with self.subTest(rule=rule, path=path):
                    self.assertNotIn((rule, path), before)
                    full = os.path.join(scratch, path)
                    saved = open(full, encoding="utf-8").read() if os.path.exists(full) else None
                    with open(full, "a", encoding="utf-8") as fh:
                        fh.write("\nvoid put_back() {\n    " + text + "\n}\n")
                    try:
                        found = [(f[0], f[1]) for f in fl.scan_tree(scratch)]
                        self.assertIn((rule, path), found)
                        self.assertEqual(fl.main(["--root", scratch]), 1)
                    finally:
                        if saved is None:
                            os.remove(full)
                        else:
                            with open(full, "w", encoding="utf-8") as fh:
                                fh.write(saved)

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
