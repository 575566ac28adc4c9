// The plain-double instantiation of the typing kernel, and its data.
#include "typing_kernel.hpp"

#include "support/wide_solver_access.hpp"
#include "tamias2d/dynamics/contacts/wide_contact_solver.hpp"

namespace tamias_bench::typing {

[[gnu::noinline]] TAMIAS_WIDE_KERNEL void run_plain(KernelData& d, int steps, double dt) {
    Kernel<PlainOps>::run(d, steps, dt);
}

KernelData make_kernel_data(int base) {
    KernelData d;
    d.bodies.push_back({}); // the static ground: zero inverse mass and inertia
    d.acc.push_back({});
    d.alpha.push_back(0.0);
    // Unit boxes of density 1: m = 1 kg, I = (1 + 1) / 12 kg m^2.
    std::vector<std::vector<std::uint32_t>> index(static_cast<std::size_t>(base));
    for (int row = 0; row < base; ++row) {
        for (int col = 0; col < base - row; ++col) {
            index[std::size_t(row)].push_back(std::uint32_t(d.bodies.size()));
            SolverBody b;
            b.inv_m = 1.0;
            b.inv_I = 6.0;
            d.bodies.push_back(b);
            d.acc.push_back({0.0, -10.0});
            d.alpha.push_back(0.0);
        }
    }
    std::vector<tamias2d::ContactConstraint> constraints;
    const auto add = [&](std::uint32_t a, std::uint32_t b, Vec2d normal, Vec2d ra1, Vec2d rb1,
                         Vec2d ra2, Vec2d rb2) {
        tamias2d::ContactConstraint c;
        c.body_a = a;
        c.body_b = b;
        c.normal = normal;
        c.friction = 0.6;
        c.count = 2;
        c.points[0].r_a = ra1;
        c.points[0].r_b = rb1;
        c.points[1].r_a = ra2;
        c.points[1].r_b = rb2;
        constraints.push_back(c);
    };
    const Vec2d up{0.0, 1.0}, right{1.0, 0.0};
    for (int row = 0; row < base; ++row) {
        const int n = base - row;
        for (int col = 0; col < n; ++col) {
            const std::uint32_t me = index[std::size_t(row)][std::size_t(col)];
            const double x = col - 0.5 * (n - 1);
            if (row == 0) {
                // Ground centred at (0, -0.5): anchors relative to it and to the box.
                add(0, me, up, {x - 0.5, 0.5}, {-0.5, -0.5}, {x + 0.5, 0.5}, {0.5, -0.5});
            } else {
                // Resting on the two boxes below, half a box each.
                const auto& below = index[std::size_t(row - 1)];
                add(below[std::size_t(col)], me, up, {0.0, 0.5}, {-0.5, -0.5}, {0.5, 0.5},
                    {0.0, -0.5});
                add(below[std::size_t(col + 1)], me, up, {-0.5, 0.5}, {0.0, -0.5}, {0.0, 0.5},
                    {0.5, -0.5});
            }
            if (col + 1 < n) {
                add(me, index[std::size_t(row)][std::size_t(col + 1)], right, {0.5, -0.5},
                    {-0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5});
            }
        }
    }
    // Prepared and packed by the engine itself, as World::solve does each step.
    tamias2d::test::prepare_contacts(constraints, d.bodies);
    tamias2d::WideContactSolver solver;
    tamias2d::test::load(solver, constraints, d.bodies);
    const auto packs = tamias2d::WideContactSolverAccess::packs(solver);
    d.packs.assign(packs.begin(), packs.end());
    d.constraints = int(constraints.size());
    return d;
}

} // namespace tamias_bench::typing
