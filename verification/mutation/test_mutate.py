"""The mutation tool's own test: which mutants a fragment of C++ yields (no build).
Oracle: the mutants of each hand-written line, listed by hand."""
import os
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mutate  # noqa: E402


def ops(code):
    return [(m["line"], m["op"], m["after"].strip()) for m in mutate.mutants_of("f.hpp", code)]


class Mutants(unittest.TestCase):
    def test_operators(self):
        self.assertEqual(ops("    return a + b * c;"),
                         [(1, "arith + to -", "return a - b * c;"),
                          (1, "arith * to /", "return a + b / c;")])
        self.assertEqual(ops("    if (x <= y)"), [(1, "compare <= to <", "if (x < y)")])

    def test_constants_and_removed_statements(self):
        got = ops("    v.x = 0.5 * w;")
        self.assertIn((1, "constant 0.5 to 1.0", "v.x = 1.0 * w;"), got)
        self.assertIn((1, "statement removed", ""), got)
        self.assertIn((1, "constant 0.0 to 1.0", "z = 1.0;"), ops("    z = 0.0;"))
        # A declaration is not removed (the mutant would not compile).
        self.assertNotIn("statement removed", [o for _, o, _ in ops("    const double k = a;")])

    def test_what_is_left_alone(self):
        for code in ("// a + b", "    x++;", "#include <a>", "template <class V> V f();",
                     '    s = "a + b";', "/* a\n   + b */", "    p->q;"):
            with self.subTest(code=code):
                self.assertEqual([o for o in ops(code) if not o[1].startswith("statement")], [])

    def test_labels_and_listing(self):
        with tempfile.TemporaryDirectory() as root:
            d = os.path.join(root, "src/tamias2d/model")
            os.makedirs(d)
            os.makedirs(os.path.join(root, "src/tamias2d/dynamics"))
            with open(os.path.join(d, "x.hpp"), "w") as fh:
                fh.write("/// \\\\srs{DD8, IM3} j\ninline double j(double a) { return -a * 2.0; }\n")
            self.assertEqual(mutate.labels_of(root, "src/tamias2d/model/x.hpp"), ["DD8", "IM3"])
            # A file without tags takes those of the headers it includes.
            with open(os.path.join(root, "src/tamias2d/dynamics/y.cpp"), "w") as fh:
                fh.write('#include "tamias2d/model/x.hpp"\nint y;\n')
            self.assertEqual(mutate.labels_of(root, "src/tamias2d/dynamics/y.cpp"), ["DD8", "IM3"])
            muts = mutate.all_mutants(root)
            self.assertEqual([m["op"] for m in muts], ["arith * to /", "constant 2.0 to 4.0"])
            self.assertEqual([m["id"] for m in muts], [0, 1])  # y.cpp has nothing to mutate


if __name__ == "__main__":
    unittest.main()
