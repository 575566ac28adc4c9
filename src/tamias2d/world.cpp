#include "tamias2d/world.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>

#include "tamias2d/collision/broad_phase.hpp"
#include "tamias2d/collision/narrow_phase.hpp"
#include "tamias2d/dynamics/body.hpp"
#include "tamias2d/dynamics/contact.hpp"
#include "tamias2d/dynamics/contact_solver.hpp"
#include "tamias2d/dynamics/model_bridge.hpp"
#include "tamias2d/dynamics/shape.hpp"
#include "tamias2d/dynamics/sleep.hpp"
#include "tamias2d/dynamics/wide_contact_solver.hpp"
#include "tamias2d/errors.hpp"
#include "tamias2d/geometry/mass_properties.hpp"
#include "tamias2d/geometry/shape_aabb.hpp"
#include "tamias2d/geometry/shape_queries.hpp"
#include "tamias2d/math/prefetch.hpp"
#include "tamias2d/memory/large_array.hpp"
#include "tamias2d/memory/pair_map.hpp"
#include "tamias2d/model/dd10_impulse.hpp"
#include "tamias2d/model/dd13_torque.hpp"
#include "tamias2d/model/dd15_kinetic_energy.hpp"
#include "tamias2d/model/dd16_potential_energy.hpp"
#include "tamias2d/model/gd1_conservation_of_momentum.hpp"
#include "tamias2d/units/angle.hpp"
#include "tamias2d/validation.hpp"

namespace tamias2d {

namespace u = tamias2d::units;

struct World::Impl {
    WorldDef def;
    double time = 0.0;
    double time_error = 0.0; ///< Kahan compensation: n steps of dt read back as n dt
    LargeArray<Body> bodies;
    std::vector<BodySettings> body_settings; ///< per body, indexed alike
    /// Per body, indexed alike: its handles' generation (only handle checks read it, so it is
    /// kept out of Body, which a step streams three times).
    std::vector<std::uint32_t> body_generation;
    std::vector<std::uint32_t> free_bodies;
    /// Per body, indexed alike: awake or asleep, and for how long at rest (read by the step only
    /// with sleeping on, def.enable_sleep).
    std::vector<SleepState> sleep_states;
    std::uint32_t loaded_bodies = 0; ///< live bodies with a load function
    LargeArray<Shape> shapes;
    std::vector<ShapeDef> shape_defs; ///< per shape, indexed alike: what it was made from
    std::vector<std::uint32_t> free_shapes;
    LargeArray<Contact> contacts;
    /// Per contact, indexed alike: what the colouring needs of it, written by the narrow phase
    /// while the contact is in cache. (Reading it back from the contacts cost a pass over most
    /// of their lines: 3.8 MB per step at 16k boxes.)
    struct EdgeInput {
        std::uint32_t body_a, body_b;
        PathGroup group;
        bool touching, bounces;
    };
    std::vector<EdgeInput> edge_inputs;
    /// Per contact, indexed alike: the accumulated impulses (warm start) and the last step's
    /// totals (contact report).
    LargeArray<ContactImpulses> warm_impulses, total_impulses;
    PairMap contact_index; ///< contact by Contact::key of its shapes
    BroadPhase broad_phase;
    /// The proxies follow_body moved, for one BroadPhase::move_proxies call (apply_moves).
    std::vector<BroadPhase::ProxyMove> proxy_moves;
    /// The shapes follow_pose could not decide, for refit_fat_box (step scratch).
    std::vector<std::uint32_t> undecided_shapes;

    // Per-step scratch, kept to avoid allocation in steady state.
    std::vector<Load> loads;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> new_pairs;
    std::vector<std::uint32_t> doomed;
    LargeArray<SolverBody> solver_bodies;
    std::vector<Vec2d> accelerations;
    std::vector<double> angular_accelerations;
    std::vector<double> linear_decay, angular_decay; ///< IM5's factors per solver body
    bool any_damped = false; ///< this step: some solver body is damped (else no factors)
    std::vector<std::uint32_t> solver_index; ///< per body: its SolverBody (0: static)
    std::vector<GraphEdge> edges;            ///< the touching manifolds, creation order
    std::vector<std::uint32_t> edge_contact; ///< per edge: its contact
    std::vector<std::uint32_t> edge_slot;    ///< per edge: its copy in `bouncing`, or no_slot
    std::vector<ContactConstraint> bouncing; ///< manifolds with restitution, creation order
    WideContactSolver wide_solver;
    // Sleeping's per-step scratch: the islands, and per island (at its representative) whether
    // a body of it is awake and its bodies' shortest time at rest.
    Islands islands;
    std::vector<std::uint8_t> island_awake;
    std::vector<double> island_rest;
    // The contact report is built when first asked for after a step or a destruction: most
    // steps of a game never read it, and copying every contact out each step cost a few
    // percent of a pile's step.
    std::vector<ContactInfo> infos;
    bool infos_stale = true;
    std::vector<ContactEvent> begin_events, end_events;

    explicit Impl(const WorldDef& d) : def(d) {}

    Body& body(BodyId id) {
        if (id.index >= bodies.size() || !bodies[id.index].alive ||
            body_generation[id.index] != id.generation) {
            throw InvalidHandle("stale or unknown BodyId " + std::to_string(id.index) + ":" +
                                std::to_string(id.generation));
        }
        return bodies[id.index];
    }
    const Body& body(BodyId id) const { return const_cast<Impl*>(this)->body(id); }

    Shape& shape(ShapeId id) {
        if (id.index >= shapes.size() || !shapes[id.index].alive() ||
            shapes[id.index].generation != id.generation) {
            throw InvalidHandle("stale or unknown ShapeId " + std::to_string(id.index) + ":" +
                                std::to_string(id.generation));
        }
        return shapes[id.index];
    }

    BodyId body_id(std::uint32_t i) const { return {i, body_generation[i]}; }

    /// Moves this step: alive, not static, and awake (every such body is, with sleeping off).
    bool active(std::uint32_t i) const { return sleep_states[i].awake; }
    bool any_awake() const {
        return std::any_of(sleep_states.begin(), sleep_states.end(),
                           [](const SleepState& st) { return st.awake; });
    }
    /// Wakes the body (and so, at the next step, its island); its time at rest starts again.
    void wake(std::uint32_t i) {
        SleepState& st = sleep_states[i];
        if (!st.movable)
            return;
        st.awake = true;
        st.sleep_time = 0.0;
    }
    /// Wakes every body touching body i: what keeps them up may have gone (a static body does
    /// not move in a step, so its contacts with sleeping bodies are not updated).
    void wake_touching(std::uint32_t i) {
        for (const Contact& c : contacts) {
            if (c.touching && (c.body_a == i || c.body_b == i)) {
                wake(c.body_a);
                wake(c.body_b);
            }
        }
    }
    ShapeId shape_id(std::uint32_t i) const { return {i, shapes[i].generation}; }

    Aabb shape_box(const Shape& s) const { return compute_aabb(s.collider, bodies[s.body].xf); }

    /// Copies the body's pose into its shapes (Shape::body_xf, body_center) after a mass update
    /// moved its centre, so that the narrow phase may read the shapes' copies.
    void sync_shape_poses(const Body& b) {
        for (std::uint32_t s = b.first_shape; s != null_index; s = shapes[s].next) {
            shapes[s].body_xf = b.xf;
            shapes[s].body_center = b.center;
        }
    }

    /// Brings a shape's copies up to its body after the body moved: the pose, and the fat box
    /// if the shape left it (the common case, still inside, reads no tree node).
    void follow_body(Shape& sh, const Body& b) {
        if (!follow_pose(sh, b))
            refit_fat_box(sh);
    }
    /// follow_body's first half: the pose, and whether the shape surely stayed inside its fat
    /// box, decided from the collider's header without the vertex lines (if not, refit_fat_box
    /// must follow).
    bool follow_pose(Shape& sh, const Body& b) {
        sh.body_xf = b.xf;
        sh.body_center = b.center;
        return surely_inside(sh.collider, b.xf, sh.fat_box);
    }
    /// follow_body's second half: the tight box from the vertex lines, and a new fat box if the
    /// shape left the old one.
    void refit_fat_box(Shape& sh) {
        const Aabb tight = compute_aabb(sh.collider, sh.body_xf);
        if (!contains(sh.fat_box, tight)) {
            sh.fat_box = broad_phase.fattened(tight);
            proxy_moves.push_back({sh.proxy, sh.fat_box});
        }
    }

    void apply_moves() {
        broad_phase.move_proxies(proxy_moves);
        proxy_moves.clear();
    }

    /// Mass, centre of mass and inertia from the shapes (DD1, DD14) or the overrides.
    void update_mass(std::uint32_t i) {
        Body& b = bodies[i];
        const BodySettings& set = body_settings[i];
        b.mass = b.inv_mass = b.inertia = b.inv_inertia = 0.0;
        b.local_center = {};
        if (b.type == BodyType::dynamic) {
            std::vector<MassData> parts;
            for (std::uint32_t s = b.first_shape; s != null_index; s = shapes[s].next) {
                const ShapeDef& d = shape_defs[s];
                parts.push_back(compute_mass(d.geometry, d.material.density));
            }
            MassData md{};
            if (!parts.empty())
                md = combine(parts);
            b.local_center = md.center;
            const double shape_mass = md.mass;
            b.mass = set.mass_override.value_or(parts.empty() ? 1.0 : shape_mass);
            // With the mass overridden, keep the shapes' distribution: scale I with the mass.
            double inertia = md.inertia;
            if (set.mass_override && shape_mass > 0.0)
                inertia *= b.mass / shape_mass;
            b.inertia = set.inertia_override.value_or(inertia);
            b.inv_mass = 1.0 / b.mass;
            b.inv_inertia = (set.fixed_rotation || !(b.inertia > 0.0)) ? 0.0 : 1.0 / b.inertia;
        }
        b.center = transform_point(b.xf, b.local_center);
        sync_shape_poses(b);
    }

    void destroy_contact(std::uint32_t i) {
        infos_stale = true; // a destroyed body's or shape's contacts leave the report at once
        Contact& c = contacts[i];
        if (c.touching) {
            wake(c.body_a); // what held the other up, or pushed it, is gone
            wake(c.body_b);
            end_events.push_back({shape_id(c.shape_a), shape_id(c.shape_b),
                                  body_id(shapes[c.shape_a].body),
                                  body_id(shapes[c.shape_b].body)});
        }
        contact_index.erase(Contact::key(c.shape_a, c.shape_b));
        const std::uint32_t last = std::uint32_t(contacts.size() - 1);
        if (i != last) {
            contacts[i] = contacts[last];
            warm_impulses[i] = warm_impulses[last];
            total_impulses[i] = total_impulses[last];
            edge_inputs[i] = edge_inputs[last];
            contact_index.assign(Contact::key(contacts[i].shape_a, contacts[i].shape_b), i);
        }
        contacts.pop_back();
        warm_impulses.pop_back();
        total_impulses.pop_back();
        edge_inputs.pop_back();
    }

    void destroy_contacts_of_shape(std::uint32_t s) {
        for (std::uint32_t i = std::uint32_t(contacts.size()); i-- > 0;) {
            if (contacts[i].shape_a == s || contacts[i].shape_b == s)
                destroy_contact(i);
        }
    }

    bool should_collide(std::uint32_t sa, std::uint32_t sb) const {
        const Body& a = bodies[shapes[sa].body];
        const Body& b = bodies[shapes[sb].body];
        if (shapes[sa].body == shapes[sb].body)
            return false;
        return a.type == BodyType::dynamic || b.type == BodyType::dynamic;
    }

    void find_new_contacts() {
        new_pairs.clear();
        broad_phase.update_pairs(new_pairs);
        // Most pairs the broad phase reports are contacts already (rain_16k: 78 %), so the
        // index is asked first, its slots eight pairs ahead: one line per pair, where the
        // filter's shapes and bodies are four scattered lines.
        constexpr std::size_t ahead = 8;
        for (std::size_t i = 0; i < new_pairs.size(); ++i) {
            if (i + ahead < new_pairs.size())
                contact_index.prefetch(
                    Contact::key(new_pairs[i + ahead].first, new_pairs[i + ahead].second));
            const auto [ua, ub] = new_pairs[i];
            const std::uint32_t sa = std::min(ua, ub), sb = std::max(ua, ub);
            const std::uint64_t key = Contact::key(sa, sb);
            if (contact_index.contains(key) || !should_collide(sa, sb))
                continue;
            Contact c;
            c.shape_a = sa;
            c.shape_b = sb;
            c.body_a = shapes[sa].body;
            c.body_b = shapes[sb].body;
            // Combination rules (docs/design.md): friction geometric mean, restitution max.
            const Material& ma = shape_defs[sa].material;
            const Material& mb = shape_defs[sb].material;
            c.friction = std::sqrt(ma.friction * mb.friction);
            c.restitution = std::max(ma.restitution, mb.restitution);
            contact_index.insert(key, std::uint32_t(contacts.size()));
            contacts.push_back(c);
            warm_impulses.emplace_back();
            total_impulses.emplace_back();
        }
    }

    /// What the colouring needs of a contact (EdgeInput).
    static EdgeInput edge_input(const Contact& c) {
        // (The separations only matter with two points: read for one, or none, they would
        // fetch the point lines of a pair that is apart.)
        const int n = c.manifold.count;
        const PathGroup group =
            n == 2 ? path_group(n, c.manifold.points[0].separation, c.manifold.points[1].separation)
                   : path_group(n, 0.0, 0.0);
        return {c.body_a, c.body_b, group, c.touching, c.restitution > 0.0};
    }

    /// \srs{R7} Narrow phase for every contact; contacts whose fat boxes separated are destroyed.
    /// With sleeping on, a contact between bodies that do not move this step (asleep or static)
    /// is kept as it is: neither has moved since it was last updated.
    void update_contacts() {
        doomed.clear();
        const bool sleeping = def.enable_sleep;
        constexpr std::uint32_t ahead = 6; // contacts: the shapes' lines arrive before use
        const auto count = std::uint32_t(contacts.size()); // the loop adds and removes none
        edge_inputs.resize(count);
        for (std::uint32_t i = 0; i < count; ++i) {
            if (i + ahead < count) {
                const Contact& next = contacts[i + ahead];
                // (A contact kept as it is, below, reads no shape.)
                if (!sleeping || active(next.body_a) || active(next.body_b)) {
                    for (const Shape* s : {&shapes[next.shape_a], &shapes[next.shape_b]}) {
                        prefetch(&s->fat_box);
                        prefetch(&s->body_xf);
                        prefetch(&s->collider.pairs[0]);
                        prefetch(&s->collider.pairs[1]);
                    }
                }
            }
            Contact& c = contacts[i];
            if (sleeping && !active(c.body_a) && !active(c.body_b))
                continue; // its edge input stands too, from its last update
            const Shape& sa = shapes[c.shape_a];
            const Shape& sb = shapes[c.shape_b];
            if (!overlaps(sa.fat_box, sb.fat_box)) {
                doomed.push_back(i);
                continue;
            }
            const CollideInput in{sa.body_xf, sa.body_center, sb.body_xf, sb.body_center,
                                  def.speculative_distance};
            // Warm starting needs only the old points' ids and impulses: the manifold itself is
            // rewritten in place (building a new one and copying it in cost a fifth of this loop).
            // Only the points in use are read: a pair that stays apart reads the first line only.
            const int old_count = c.manifold.count;
            ContactImpulses& warm = warm_impulses[i];
            std::uint32_t old_id[2] = {};
            double old_n[2] = {}, old_t[2] = {};
            for (int k = 0; k < old_count; ++k) {
                old_id[k] = c.manifold.points[k].id.key();
                old_n[k] = warm.normal[k];
                old_t[k] = warm.tangent[k];
            }
            collide(sa.collider, sb.collider, in, c.manifold, &c.hint);
            // Warm starting: a point keeps its impulses when the same features touch again.
            // (Chosen in registers, then stored: zeroing first made GCC call memset twice.)
            for (int j = 0; j < c.manifold.count; ++j) {
                double normal = 0.0, tangent = 0.0;
                for (int k = 0; k < old_count; ++k) {
                    if (old_id[k] == c.manifold.points[j].id.key()) {
                        normal = old_n[k];
                        tangent = old_t[k];
                    }
                }
                warm.normal[j] = normal;
                warm.tangent[j] = tangent;
            }
            const bool was = c.touching;
            c.touching = c.manifold.count > 0;
            edge_inputs[i] = edge_input(c);
            if (c.touching != was) {
                if (sleeping) { // a body met, or left, another: both islands wake
                    wake(c.body_a);
                    wake(c.body_b);
                }
                (c.touching ? begin_events : end_events)
                    .push_back({shape_id(c.shape_a), shape_id(c.shape_b), body_id(sa.body),
                                body_id(sb.body)});
            }
        }
        // Descending, so swap-removal never moves a contact that is still to be removed.
        for (auto it = doomed.rbegin(); it != doomed.rend(); ++it)
            destroy_contact(*it); // moves the last contact into the gap
    }

    /// A manifold as the solver takes it, before preparation: bodies, normal, materials, anchors,
    /// separations and the impulses to warm start from.
    void unprepared_constraint(ContactConstraint& cc, const GraphEdge& edge,
                               std::uint32_t contact) const {
        const Contact& c = contacts[contact];
        const ContactImpulses& warm = warm_impulses[contact];
        cc.body_a = edge.body_a;
        cc.body_b = edge.body_b;
        cc.contact = contact;
        cc.normal = c.manifold.normal;
        cc.friction = c.friction;
        cc.restitution = c.restitution;
        cc.count = c.manifold.count;
        for (int j = 0; j < cc.count; ++j) {
            const ManifoldPoint& mp = c.manifold.points[j];
            ContactConstraintPoint& cp = cc.points[j];
            cp.r_a = mp.anchor_a;
            cp.r_b = mp.anchor_b;
            cp.base_separation = mp.separation;
            cp.normal_impulse = warm.normal[j];
            cp.tangent_impulse = warm.tangent[j];
        }
    }

    /// The solver bodies and their accelerations (IM1, IM2's loads). Built before the narrow
    /// phase, not after it: a pass over every body between the narrow phase's sweep of the
    /// contacts and the lane filling's gather of them pushed them out of the cache (rain_16k).
    void prepare_bodies(double h) {
        // Solver body 0 is the shared immovable body standing in for every static body.
        solver_bodies.assign(1, SolverBody{});
        solver_index.resize(bodies.size());
        accelerations.assign(1, Vec2d{});
        angular_accelerations.assign(1, 0.0);
        any_damped = false;
        linear_decay.assign(1, 1.0);
        angular_decay.assign(1, 1.0);
        for (std::uint32_t i = 0; i < bodies.size(); ++i) {
            Body& b = bodies[i];
            // A sleeping body is immovable this step, as a static one is.
            if ((def.enable_sleep && !sleep_states[i].awake) || !b.alive ||
                b.type == BodyType::static_body) {
                solver_index[i] = 0;
                continue;
            }
            solver_index[i] = std::uint32_t(solver_bodies.size());
            solver_bodies.push_back({b.v, b.w, b.inv_mass, b.inv_inertia, {}, 0.0});
            Vec2d a{};
            double alpha = 0.0;
            if (b.type == BodyType::dynamic) {
                // Unloaded, F = 0 and tau = 0 give g and 0 bit for bit whatever m and I (0 / m is
                // exactly 0), so the body's third line, loads and masses, is not read.
                Vec2d f{};
                double tau = 0.0, mass = 1.0, inertia = 1.0;
                if (b.loaded || !loads.empty()) {
                    const Load l = loads.empty() ? Load{} : loads[i];
                    f = b.force + b.force_once + l.force;
                    tau = b.torque + b.torque_once + l.torque;
                    mass = b.mass;
                    inertia = b.inertia;
                }
                a = bridge::acceleration(b.gravity_scale * def.gravity, f, mass);
                alpha = b.inv_inertia > 0.0 ? bridge::angular_acceleration(tau, inertia) : 0.0;
            }
            accelerations.push_back(a);
            angular_accelerations.push_back(alpha);
            if (b.damped && !any_damped) { // the first damped body: undamped ones get 1
                any_damped = true;
                linear_decay.resize(solver_bodies.size() - 1, 1.0);
                angular_decay.resize(solver_bodies.size() - 1, 1.0);
            }
            if (any_damped) {
                const BodySettings& set = body_settings[i];
                linear_decay.push_back(b.damped ? bridge::decay_factor(set.linear_damping, h)
                                                : 1.0);
                angular_decay.push_back(b.damped ? bridge::decay_factor(set.angular_damping, h)
                                                 : 1.0);
            }
        }
    }

    /// \srs{R5} \srs{R6} IM1/IM2, the velocity half of the semi-implicit Euler step (DD4, DD7);
    /// \srs{IM5} with damping when some body is damped. IM5's factor 1 gives IM1/IM2's bits, so
    /// the undamped loop is only the cheaper form of the same step (no factors to stream).
    void integrate_velocities(double h) {
        if (any_damped) {
            for (std::size_t k = 1; k < solver_bodies.size(); ++k) {
                SolverBody& sb = solver_bodies[k];
                sb.v = bridge::velocity_step(sb.v, accelerations[k], h, linear_decay[k]);
                sb.w = bridge::angular_velocity_step(sb.w, angular_accelerations[k], h,
                                                     angular_decay[k]);
            }
            return;
        }
        for (std::size_t k = 1; k < solver_bodies.size(); ++k) {
            SolverBody& sb = solver_bodies[k];
            sb.v += bridge::velocity_change(accelerations[k], h);
            sb.w += bridge::angular_velocity_change(angular_accelerations[k], h);
        }
    }

    void solve(double dt) {
        const int n = def.substeps;
        const double h = dt / n;
        // The touching manifolds in creation order, as the colouring sees them; those that can
        // bounce get a slot for the restitution pass's copy, also in creation order.
        edges.clear();
        edge_contact.clear();
        edge_slot.clear();
        std::uint32_t bounce_count = 0;
        for (std::uint32_t i = 0; i < edge_inputs.size(); ++i) {
            const EdgeInput& e = edge_inputs[i];
            if (!e.touching)
                continue;
            const std::uint32_t a = solver_index[e.body_a], b = solver_index[e.body_b];
            if (a == 0 && b == 0)
                continue; // both asleep or static (only with sleeping on): nothing to solve
            edges.push_back({a, b, e.group});
            edge_contact.push_back(i);
            edge_slot.push_back(e.bounces ? bounce_count++ : WideContactSolver::no_slot);
        }
        if (bouncing.size() < bounce_count)
            bouncing.resize(bounce_count); // only while the scene grows: never shrunk
        wide_solver.colour(edges, solver_bodies.size());
        // Those that can bounce get a scalar copy for the restitution pass, prepared from the
        // velocities before the step (DD11's relative velocity before the impact).
        for (std::uint32_t k = 0; k < edges.size(); ++k) {
            if (edge_slot[k] == WideContactSolver::no_slot)
                continue;
            ContactConstraint& copy = bouncing[edge_slot[k]];
            unprepared_constraint(copy, edges[k], edge_contact[k]);
            prepare_contact(copy, solver_bodies);
        }
        // The first substep's velocity half comes before the preparation, so that each pack can
        // be warm started as soon as it is prepared (below), as warm_start would after it.
        integrate_velocities(h);
        // The manifolds are prepared straight into their packs, four lanes at once, in solve
        // order (a per-step array of prepared constraints cost a pass over ~300 bytes each).
        const auto order = wide_solver.order();
        ContactConstraint cc; // reused: what set_input_lane reads is set anew
        // Reused too: every lane is set or cleared each pack (clearing the whole input per pack,
        // 600 bytes, was a tenth of this loop's time).
        WideManifoldInput in;
        // The packs read the contacts level by level, a sparse sweep the hardware prefetcher
        // does not follow once the contacts outgrow the caches: ask for them four packs ahead.
        constexpr std::size_t ahead = 4;
        for (std::size_t p = 0; p < order.size(); ++p) {
            if (p + ahead < order.size()) {
                for (int l = 0; l < wide_lanes; ++l) {
                    const std::uint32_t k = order[p + ahead][l];
                    if (k == ConstraintGraph::no_constraint)
                        continue;
                    const char* c = reinterpret_cast<const char*>(&contacts[edge_contact[k]]);
                    for (std::size_t line = 0; line < sizeof(Contact); line += 64)
                        prefetch(c + line);
                    prefetch(&warm_impulses[edge_contact[k]]);
                }
            }
            for (int l = 0; l < wide_lanes; ++l) {
                const std::uint32_t k = order[p][l];
                if (k == ConstraintGraph::no_constraint) {
                    clear_input_lane(in, l);
                    continue;
                }
                unprepared_constraint(cc, edges[k], edge_contact[k]);
                set_input_lane(in, l, cc, edge_slot[k]);
            }
            wide_solver.prepare_pack_and_warm_start(p, in, solver_bodies);
        }

        ContactSolverSettings st;
        st.inv_h = 1.0 / h;
        // The contact spring is kept below a quarter of the substep rate to stay stable.
        st.softness =
            make_softness(std::min(def.contact_hertz, 0.25 * n / dt), def.contact_damping_ratio, h);
        st.linear_slop = def.linear_slop;
        st.push_max_velocity = def.contact_push_max_velocity;
        st.restitution_threshold = def.restitution_threshold;

        const std::size_t nb = solver_bodies.size();
        for (int sub = 0; sub < n; ++sub) {
            if (sub > 0) { // the first substep's were done with the preparation
                integrate_velocities(h);
                wide_solver.warm_start(solver_bodies);
            }
            wide_solver.solve(solver_bodies, st, true);
            // IM1/IM2, position half with the new velocities (DD3, DD6).
            for (std::size_t k = 1; k < nb; ++k) {
                SolverBody& sb = solver_bodies[k];
                sb.dp += bridge::displacement(sb.v, h);
                sb.dq += bridge::rotation(sb.w, h);
            }
            wide_solver.solve(solver_bodies, st, false);
        }
        const std::span<ContactConstraint> bouncers(bouncing.data(), bounce_count);
        wide_solver.store(warm_impulses, total_impulses, bouncers);
        // \srs{R8} Post-collision velocities (and, integrated, positions) of colliding bodies.
        apply_restitution(bouncers, solver_bodies, st);
        for (const ContactConstraint& b : bouncers) {
            for (int j = 0; j < b.count; ++j)
                total_impulses[b.contact].normal[j] = b.points[j].total_normal_impulse;
        }

        // Bodies and shapes are swept in order, but the sweep reads two lines of each shape
        // at a 384-byte stride beside the bodies', which the hardware prefetcher does not keep
        // ahead of at 16k boxes: ask for the bodies 16 ahead and their first shapes 8 ahead.
        // (The vertex lines are read only by a shape the header's bound cannot decide.)
        constexpr std::uint32_t body_ahead = 16, shape_ahead = 8;
        const auto body_count = std::uint32_t(bodies.size());
        undecided_shapes.reserve(shapes.size()); // allocates only after shapes were added
        // Solver body 0 stands for the bodies that did not move: static, asleep or destroyed
        // (their lines are neither asked for nor read).
        for (std::uint32_t i = 0; i < body_count; ++i) {
            if (i + body_ahead < body_count && solver_index[i + body_ahead] != 0) {
                // Its first two lines: the third only if it is loaded (rare).
                const char* p = reinterpret_cast<const char*>(&bodies[i + body_ahead]);
                for (std::size_t line = 0; line < offsetof(Body, force); line += 64)
                    prefetch(p + line);
            }
            if (i + shape_ahead < body_count && solver_index[i + shape_ahead] != 0) {
                const std::uint32_t s = bodies[i + shape_ahead].first_shape;
                if (s != null_index) {
                    const Shape& sh = shapes[s];
                    prefetch(&sh.fat_box);
                    prefetch(&sh.body_xf);
                }
            }
            if (solver_index[i] == 0)
                continue;
            Body& b = bodies[i];
            const SolverBody& sb = solver_bodies[solver_index[i]];
            b.v = sb.v;
            b.w = sb.w;
            b.center += sb.dp;
            b.angle += sb.dq;
            b.xf.q = Rot::from_angle(b.angle);
            b.xf.p = b.center - rotate(b.xf.q, b.local_center);
            if (b.loaded) {
                b.force_once = {};
                b.torque_once = 0.0;
                b.loaded = !b.unloaded();
            }
            // The shapes' copies, in the same pass.
            for (std::uint32_t s = b.first_shape; s != null_index; s = shapes[s].next) {
                if (!follow_pose(shapes[s], b))
                    undecided_shapes.push_back(s);
            }
        }
        // The shapes the header could not decide (moving ones) read their vertex lines, which the
        // sweep does not ask for: read after the sweep, a few shapes ahead, rather than waited
        // for one by one inside it. The same shapes in the same order: the same moves.
        constexpr std::size_t refit_ahead = 4;
        for (std::size_t j = 0; j < undecided_shapes.size(); ++j) {
            if (j + refit_ahead < undecided_shapes.size()) {
                const Shape& next = shapes[undecided_shapes[j + refit_ahead]];
                const char* p = reinterpret_cast<const char*>(&next.collider);
                prefetch(p); // vertex pairs 0 and 1: a box's four vertices
                prefetch(p + 64);
                prefetch(&next.fat_box);
                prefetch(&next.body_xf);
            }
            refit_fat_box(shapes[undecided_shapes[j]]);
        }
        undecided_shapes.clear();
        apply_moves();
    }

    /// Sleeping: the islands of this step's touching contacts; an island with an awake body
    /// wakes whole (a body met a sleeping one, or was changed through the API). Run only when
    /// some body is awake (World::step), as update_sleep.
    void wake_islands() {
        islands.reset(bodies.size());
        for (std::size_t i = 0; i < contacts.size(); ++i) {
            const Contact& c = contacts[i];
            if (c.touching && sleep_states[c.body_a].movable && sleep_states[c.body_b].movable)
                islands.unite(c.body_a, c.body_b);
        }
        island_awake.assign(bodies.size(), 0);
        for (std::uint32_t i = 0; i < bodies.size(); ++i) {
            if (active(i))
                island_awake[islands.find(i)] = 1;
        }
        for (std::uint32_t i = 0; i < bodies.size(); ++i) {
            if (sleep_states[i].movable && !active(i) && island_awake[islands.find(i)])
                wake(i);
        }
    }

    /// Sleeping, after the step: each awake body's time at rest, and an island whose bodies
    /// have all been at rest for time_to_sleep falls asleep (velocities zero: they no longer
    /// move). A body that may not sleep, or carries a persistent load, is never at rest.
    void update_sleep(double dt) {
        island_rest.assign(bodies.size(), std::numeric_limits<double>::infinity());
        for (std::uint32_t i = 0; i < bodies.size(); ++i) {
            if (!active(i))
                continue;
            const Body& b = bodies[i];
            SleepState& st = sleep_states[i];
            const bool loaded = b.force.x != 0.0 || b.force.y != 0.0 || b.torque != 0.0 ||
                                bool(body_settings[i].load);
            const bool rest =
                st.enabled && !loaded &&
                at_rest(b.v, b.w, def.linear_sleep_tolerance, def.angular_sleep_tolerance);
            st.sleep_time = rest ? st.sleep_time + dt : 0.0;
            double& island = island_rest[islands.find(i)];
            island = std::min(island, rest ? st.sleep_time : -1.0); // -1: not at rest now
        }
        for (std::uint32_t i = 0; i < bodies.size(); ++i) {
            if (!active(i) || !(island_rest[islands.find(i)] >= def.time_to_sleep))
                continue;
            sleep_states[i].awake = false;
            sleep_states[i].sleep_time = 0.0;
            bodies[i].v = {};
            bodies[i].w = 0.0;
        }
    }

    void build_infos() {
        infos.clear();
        for (std::size_t i = 0; i < contacts.size(); ++i) {
            const Contact& c = contacts[i];
            if (!c.touching)
                continue;
            const ContactImpulses& total = total_impulses[i];
            ContactInfo ci;
            ci.shape_a = shape_id(c.shape_a);
            ci.shape_b = shape_id(c.shape_b);
            ci.body_a = body_id(shapes[c.shape_a].body);
            ci.body_b = body_id(shapes[c.shape_b].body);
            ci.normal = c.manifold.normal;
            ci.point_count = c.manifold.count;
            for (int j = 0; j < c.manifold.count; ++j) {
                ci.points[j] = {c.manifold.points[j].point, c.manifold.points[j].separation,
                                total.normal[j], total.tangent[j]};
            }
            infos.push_back(ci);
        }
    }
};

World::World(const WorldDef& def) {
    validate(def);
    impl_ = std::make_unique<Impl>(def);
}
World::~World() = default;
World::World(World&&) noexcept = default;
World& World::operator=(World&&) noexcept = default;

BodyId World::create_body(const BodyDef& def) {
    validate(def);
    Impl& w = *impl_;
    std::uint32_t i;
    if (!w.free_bodies.empty()) {
        i = w.free_bodies.back();
        w.free_bodies.pop_back();
    } else {
        i = std::uint32_t(w.bodies.size());
        w.bodies.emplace_back();
        w.body_settings.emplace_back();
        w.sleep_states.emplace_back();
        w.body_generation.push_back(0);
    }
    Body& b = w.bodies[i];
    const std::uint32_t generation = ++w.body_generation[i];
    b = Body{};
    b.alive = true;
    b.type = def.type;
    b.angle = def.angle;
    b.xf = {def.position, Rot::from_angle(def.angle)};
    b.v = def.type == BodyType::static_body ? Vec2d{} : def.linear_velocity;
    b.w = def.type == BodyType::static_body ? 0.0 : def.angular_velocity;
    b.force = def.force;
    b.torque = def.torque;
    b.loaded = !b.unloaded();
    b.gravity_scale = def.gravity_scale;
    w.body_settings[i] = {def.name,           def.load,           def.mass,           def.inertia,
                          def.fixed_rotation, def.linear_damping, def.angular_damping};
    b.damped =
        def.type == BodyType::dynamic && (def.linear_damping != 0.0 || def.angular_damping != 0.0);
    // With sleeping off every body is awake, whatever its definition asks.
    const bool movable = def.type != BodyType::static_body;
    w.sleep_states[i] = {0.0, movable && (def.awake || !w.def.enable_sleep), def.enable_sleep,
                         movable};
    w.loaded_bodies += def.load ? 1 : 0;
    w.update_mass(i);
    return {i, generation};
}

void World::destroy_body(BodyId id) {
    Impl& w = *impl_;
    Body& b = w.body(id);
    for (std::uint32_t s = b.first_shape; s != null_index; s = w.shapes[s].next) {
        w.destroy_contacts_of_shape(s);
        w.broad_phase.destroy_proxy(w.shapes[s].proxy);
        w.shapes[s].proxy = -1;
        w.free_shapes.push_back(s);
    }
    b.first_shape = null_index;
    b.alive = false;
    w.sleep_states[id.index] = SleepState{}; // neither awake nor movable
    BodySettings& set = w.body_settings[id.index];
    w.loaded_bodies -= set.load ? 1 : 0;
    set = BodySettings{};
    w.free_bodies.push_back(id.index);
}

ShapeId World::create_shape(BodyId body_id, const ShapeDef& def) {
    Impl& w = *impl_;
    w.body(body_id); // handle check before validation: both leave the world unchanged
    validate(def);
    std::uint32_t i;
    if (!w.free_shapes.empty()) {
        i = w.free_shapes.back();
        w.free_shapes.pop_back();
    } else {
        i = std::uint32_t(w.shapes.size());
        w.shapes.emplace_back();
        w.shape_defs.emplace_back();
    }
    Shape& s = w.shapes[i];
    s.generation += 1;
    s.body = body_id.index;
    s.next = null_index;
    s.collider = make_collider(def.geometry);
    w.shape_defs[i] = def;
    Body& b = w.bodies[body_id.index];
    // Appended, so that the body's shapes (and the mass summed over them) keep creation order.
    std::uint32_t* link = &b.first_shape;
    while (*link != null_index)
        link = &w.shapes[*link].next;
    *link = i;
    s.proxy = w.broad_phase.create_proxy(w.shape_box(s), i, b.type == BodyType::static_body);
    s.fat_box = w.broad_phase.fat_aabb(s.proxy);
    w.update_mass(body_id.index); // also copies the body's pose into its shapes
    return {i, s.generation};
}

void World::destroy_shape(ShapeId id) {
    Impl& w = *impl_;
    Shape& s = w.shape(id);
    w.destroy_contacts_of_shape(id.index);
    w.broad_phase.destroy_proxy(s.proxy);
    s.proxy = -1;
    std::uint32_t* link = &w.bodies[s.body].first_shape;
    while (*link != id.index)
        link = &w.shapes[*link].next;
    *link = s.next;
    w.free_shapes.push_back(id.index);
    w.update_mass(s.body);
}

bool World::is_valid(BodyId id) const {
    return id.index < impl_->bodies.size() && impl_->bodies[id.index].alive &&
           impl_->body_generation[id.index] == id.generation;
}
bool World::is_valid(ShapeId id) const {
    return id.index < impl_->shapes.size() && impl_->shapes[id.index].alive() &&
           impl_->shapes[id.index].generation == id.generation;
}

std::vector<BodyId> World::bodies() const {
    std::vector<BodyId> out;
    for (std::uint32_t i = 0; i < impl_->bodies.size(); ++i) {
        if (impl_->bodies[i].alive)
            out.push_back(impl_->body_id(i));
    }
    return out;
}

std::vector<ShapeId> World::shapes(BodyId id) const {
    std::vector<ShapeId> out;
    for (std::uint32_t s = impl_->body(id).first_shape; s != null_index; s = impl_->shapes[s].next)
        out.push_back(impl_->shape_id(s));
    return out;
}

std::size_t World::body_count() const {
    return impl_->bodies.size() - impl_->free_bodies.size();
}

void World::step(double dt) {
    validate_time_step(dt);
    Impl& w = *impl_;
    // Evaluate the time-varying loads first: a user function returning NaN is rejected
    // before anything has changed.
    // Most worlds have none: then the step reads no settings and `loads` stays empty.
    w.loads.clear();
    if (w.loaded_bodies > 0)
        w.loads.assign(w.bodies.size(), Load{});
    for (std::uint32_t i = 0; i < w.loads.size(); ++i) {
        const Body& b = w.bodies[i];
        const LoadFunction& load = w.body_settings[i].load;
        if (!b.alive || !load || b.type != BodyType::dynamic)
            continue;
        const Load l = load(w.time);
        require_finite("load(t).force", l.force);
        require_finite("load(t).torque", l.torque);
        w.loads[i] = l;
    }
    w.begin_events.clear();
    w.end_events.clear();
    w.find_new_contacts();
    if (w.def.enable_sleep && !w.any_awake()) {
        // Every body asleep: every contact is kept as it is (a new one, of a static body moved
        // onto sleeping ones, too) and nothing is solved; the step does only this.
        w.edge_inputs.resize(w.contacts.size());
    } else if (w.def.enable_sleep) {
        // The islands need this step's touching contacts, and the solver bodies the islands.
        w.update_contacts();
        w.wake_islands();
        w.prepare_bodies(dt / w.def.substeps);
        w.solve(dt);
        w.update_sleep(dt);
    } else {
        w.prepare_bodies(dt / w.def.substeps);
        w.update_contacts();
        w.solve(dt);
    }
    // Compensated sum, so that a load switching at t = n dt is seen at step n, not n + 1.
    const double y = dt - w.time_error;
    const double t = w.time + y;
    w.time_error = (t - w.time) - y;
    w.time = t;
    w.infos_stale = true;
}

double World::time() const {
    return impl_->time;
}
void World::set_gravity(Vec2d g) {
    require_finite("gravity", g);
    impl_->def.gravity = g;
    for (std::uint32_t i = 0; i < impl_->bodies.size(); ++i)
        impl_->wake(i); // a sleeping pile must feel the new gravity (wake skips the immovable)
}
Vec2d World::gravity() const {
    return impl_->def.gravity;
}
const WorldDef& World::settings() const {
    return impl_->def;
}

BodyState World::state(BodyId id) const {
    const Body& b = impl_->body(id);
    return {b.center, b.v, u::wrap_orientation(b.angle), b.w};
}
Vec2d World::position(BodyId id) const {
    return impl_->body(id).center;
}
Vec2d World::origin(BodyId id) const {
    return impl_->body(id).xf.p;
}
double World::orientation(BodyId id) const {
    return u::wrap_orientation(impl_->body(id).angle);
}
Vec2d World::velocity(BodyId id) const {
    return impl_->body(id).v;
}
double World::angular_velocity(BodyId id) const {
    return impl_->body(id).w;
}
double World::mass(BodyId id) const {
    return impl_->body(id).mass;
}
double World::inertia(BodyId id) const {
    return impl_->body(id).inertia;
}
Vec2d World::local_center(BodyId id) const {
    return impl_->body(id).local_center;
}
BodyType World::type(BodyId id) const {
    return impl_->body(id).type;
}
const std::string& World::name(BodyId id) const {
    impl_->body(id); // handle check
    return impl_->body_settings[id.index].name;
}

void World::set_transform(BodyId id, Vec2d origin, double angle) {
    Body& b = impl_->body(id);
    require_finite("origin", origin);
    require_finite("angle", angle);
    b.angle = angle;
    b.xf = {origin, Rot::from_angle(angle)};
    b.center = transform_point(b.xf, b.local_center);
    for (std::uint32_t s = b.first_shape; s != null_index; s = impl_->shapes[s].next)
        impl_->follow_body(impl_->shapes[s], b);
    impl_->apply_moves();
    impl_->wake(id.index);
    if (impl_->def.enable_sleep && b.type == BodyType::static_body)
        impl_->wake_touching(id.index);
}
void World::set_damping(BodyId id, double linear, double angular) {
    Body& b = impl_->body(id);
    validate_damping("linear_damping", linear);
    validate_damping("angular_damping", angular);
    BodySettings& set = impl_->body_settings[id.index];
    set.linear_damping = linear;
    set.angular_damping = angular;
    b.damped = b.type == BodyType::dynamic && (linear != 0.0 || angular != 0.0);
}
double World::linear_damping(BodyId id) const {
    impl_->body(id); // handle check
    return impl_->body_settings[id.index].linear_damping;
}
double World::angular_damping(BodyId id) const {
    impl_->body(id); // handle check
    return impl_->body_settings[id.index].angular_damping;
}

void World::set_velocity(BodyId id, Vec2d v) {
    Body& b = impl_->body(id);
    require_finite("velocity", v);
    if (b.type != BodyType::static_body)
        b.v = v;
    impl_->wake(id.index);
}
void World::set_angular_velocity(BodyId id, double omega) {
    Body& b = impl_->body(id);
    require_finite("angular_velocity", omega);
    if (b.type != BodyType::static_body)
        b.w = omega;
    impl_->wake(id.index);
}
void World::set_force(BodyId id, Vec2d force) {
    Body& b = impl_->body(id);
    require_finite("force", force);
    b.force = force;
    b.loaded = true;
    impl_->wake(id.index);
}
void World::set_torque(BodyId id, double torque) {
    Body& b = impl_->body(id);
    require_finite("torque", torque);
    b.torque = torque;
    b.loaded = true;
    impl_->wake(id.index);
}
void World::apply_force(BodyId id, Vec2d force, Vec2d world_point) {
    Body& b = impl_->body(id);
    require_finite("force", force);
    require_finite("world_point", world_point);
    b.force_once += force;
    b.loaded = true;
    b.torque_once += model::dd13::torque(bridge::typed<u::Length>(world_point - b.center),
                                         bridge::typed<u::Force>(force))
                         .value();
    impl_->wake(id.index);
}
void World::apply_torque(BodyId id, double torque) {
    Body& b = impl_->body(id);
    require_finite("torque", torque);
    b.torque_once += torque;
    b.loaded = true;
    impl_->wake(id.index);
}
void World::apply_impulse(BodyId id, Vec2d impulse, Vec2d world_point) {
    Body& b = impl_->body(id);
    require_finite("impulse", impulse);
    require_finite("world_point", world_point);
    if (b.type != BodyType::dynamic)
        return;
    impl_->wake(id.index);
    const double magnitude = length(impulse);
    if (magnitude == 0.0)
        return;
    // IM3's impulse application (DD10 for v, r x J / I for omega), against an immovable body.
    SolverBody ground{};
    SolverBody self{b.v, b.w, b.inv_mass, b.inv_inertia, {}, 0.0};
    const Vec2d n = impulse / magnitude;
    bridge::apply_impulse(ground, self, 0.0, bridge::moment_arm(world_point - b.center, n), n,
                          magnitude);
    b.v = self.v;
    b.w = self.w;
}
void World::set_load(BodyId id, LoadFunction load) {
    impl_->body(id); // handle check
    LoadFunction& old = impl_->body_settings[id.index].load;
    impl_->loaded_bodies += (load ? 1 : 0) - (old ? 1 : 0);
    old = std::move(load);
    impl_->wake(id.index);
}

bool World::is_awake(BodyId id) const {
    impl_->body(id); // handle check
    return impl_->sleep_states[id.index].awake;
}
void World::set_awake(BodyId id, bool awake) {
    Body& b = impl_->body(id);
    if (awake) {
        impl_->wake(id.index);
        return;
    }
    if (!impl_->def.enable_sleep || b.type == BodyType::static_body)
        return; // with sleeping off every body stays awake
    impl_->sleep_states[id.index].awake = false;
    impl_->sleep_states[id.index].sleep_time = 0.0;
    b.v = {};
    b.w = 0.0;
    b.force_once = {};
    b.torque_once = 0.0;
}

double World::kinetic_energy() const {
    double e = 0.0;
    for (const Body& b : impl_->bodies) {
        if (!b.alive || b.type != BodyType::dynamic)
            continue;
        const double inertia = b.inv_inertia > 0.0 ? b.inertia : 0.0;
        e += model::dd15::kinetic_energy(
                 u::from_value<u::Mass>(b.mass), bridge::typed<u::Velocity>(b.v),
                 u::from_value<u::MomentOfInertia>(inertia), u::from_value<u::AngularVelocity>(b.w))
                 .value();
    }
    return e;
}
double World::potential_energy() const {
    double e = 0.0;
    for (const Body& b : impl_->bodies) {
        if (!b.alive || b.type != BodyType::dynamic)
            continue;
        e += model::dd16::potential_energy(
                 u::from_value<u::Mass>(b.mass),
                 bridge::typed<u::Acceleration>(b.gravity_scale * impl_->def.gravity),
                 bridge::typed<u::Length>(b.center))
                 .value();
    }
    return e;
}
Vec2d World::linear_momentum() const {
    std::vector<model::gd1::MassVelocity> mv;
    for (const Body& b : impl_->bodies) {
        if (!b.alive || b.type != BodyType::dynamic)
            continue;
        mv.push_back({u::from_value<u::Mass>(b.mass), bridge::typed<u::Velocity>(b.v)});
    }
    return bridge::plain(model::gd1::total_momentum(mv));
}

std::span<const ContactInfo> World::contacts() const {
    if (impl_->infos_stale) {
        impl_->build_infos();
        impl_->infos_stale = false;
    }
    return impl_->infos;
}
std::span<const ContactEvent> World::contact_begin_events() const {
    return impl_->begin_events;
}
std::span<const ContactEvent> World::contact_end_events() const {
    return impl_->end_events;
}

std::vector<ShapeId> World::query_aabb(const Aabb& box) const {
    std::vector<ShapeId> out;
    impl_->broad_phase.query(box, [&](int proxy) {
        const std::uint32_t s = impl_->broad_phase.user_data(proxy);
        if (overlaps(impl_->shape_box(impl_->shapes[s]), box))
            out.push_back(impl_->shape_id(s));
        return true;
    });
    std::sort(out.begin(), out.end(), [](ShapeId a, ShapeId b) { return a.index < b.index; });
    return out;
}

std::vector<ShapeId> World::query_point(Vec2d p) const {
    std::vector<ShapeId> out;
    const Aabb box{p.x, p.y, p.x, p.y};
    impl_->broad_phase.query(box, [&](int proxy) {
        const std::uint32_t s = impl_->broad_phase.user_data(proxy);
        const Shape& sh = impl_->shapes[s];
        if (test_point(impl_->shape_defs[s].geometry, impl_->bodies[sh.body].xf, p))
            out.push_back(impl_->shape_id(s));
        return true;
    });
    std::sort(out.begin(), out.end(), [](ShapeId a, ShapeId b) { return a.index < b.index; });
    return out;
}

std::optional<RayCastHit> World::ray_cast(Vec2d origin, Vec2d translation) const {
    require_finite("origin", origin);
    require_finite("translation", translation);
    const Vec2d end = origin + translation;
    const Aabb box{std::min(origin.x, end.x), std::min(origin.y, end.y), std::max(origin.x, end.x),
                   std::max(origin.y, end.y)};
    std::optional<RayCastHit> best;
    impl_->broad_phase.query(inflated(box, 1e-9), [&](int proxy) {
        const std::uint32_t s = impl_->broad_phase.user_data(proxy);
        const Shape& sh = impl_->shapes[s];
        const auto hit = tamias2d::ray_cast(impl_->shape_defs[s].geometry,
                                            impl_->bodies[sh.body].xf, origin, translation);
        if (hit && (!best || hit->fraction < best->fraction ||
                    (hit->fraction == best->fraction && s < best->shape.index))) {
            best = RayCastHit{impl_->shape_id(s), impl_->body_id(sh.body), hit->point, hit->normal,
                              hit->fraction};
        }
        return true;
    });
    return best;
}

namespace {
struct Hasher {
    std::uint64_t h = 1469598103934665603ull;
    void bytes(const void* p, std::size_t n) {
        const auto* c = static_cast<const unsigned char*>(p);
        for (std::size_t i = 0; i < n; ++i) {
            h ^= c[i];
            h *= 1099511628211ull;
        }
    }
    void operator()(double v) { bytes(&v, sizeof v); }
    void operator()(Vec2d v) {
        (*this)(v.x);
        (*this)(v.y);
    }
    void operator()(std::uint64_t v) { bytes(&v, sizeof v); }
};
} // namespace

std::uint64_t World::state_hash() const {
    const Impl& w = *impl_;
    Hasher hs;
    hs(w.time);
    hs(w.time_error);
    hs(w.def.gravity);
    hs(std::uint64_t(w.bodies.size()));
    for (std::uint32_t i = 0; i < w.bodies.size(); ++i) {
        const Body& b = w.bodies[i];
        const BodySettings& set = w.body_settings[i];
        hs(std::uint64_t(w.body_generation[i]) << 8 | std::uint64_t(b.alive) << 4 |
           std::uint64_t(b.type));
        if (!b.alive)
            continue;
        hs(b.xf.p);
        hs(b.xf.q.c);
        hs(b.xf.q.s);
        hs(b.angle);
        hs(b.center);
        hs(b.local_center);
        hs(b.v);
        hs(b.w);
        hs(b.force);
        hs(b.torque);
        hs(b.force_once);
        hs(b.torque_once);
        hs(b.mass);
        hs(b.inertia);
        hs(b.inv_mass);
        hs(b.inv_inertia);
        hs(b.gravity_scale);
        hs(std::uint64_t(set.fixed_rotation) << 1 | std::uint64_t(bool(set.load)));
        if (b.damped) { // (so that undamped worlds hash as they always did)
            hs(set.linear_damping);
            hs(set.angular_damping);
        }
        if (w.def.enable_sleep) { // (so that worlds without sleeping hash as they always did)
            const SleepState& st = w.sleep_states[i];
            hs(st.sleep_time);
            hs(std::uint64_t(st.awake) << 1 | std::uint64_t(st.enabled));
        }
        hs.bytes(set.name.data(), set.name.size());
        for (std::uint32_t s = b.first_shape; s != null_index; s = w.shapes[s].next)
            hs(std::uint64_t(s));
    }
    hs(std::uint64_t(w.shapes.size()));
    for (std::uint32_t i = 0; i < w.shapes.size(); ++i) {
        const Shape& s = w.shapes[i];
        hs(std::uint64_t(s.generation) << 1 | std::uint64_t(s.alive()));
        if (!s.alive())
            continue;
        const ShapeDef& d = w.shape_defs[i];
        hs(std::uint64_t(s.body));
        hs(std::uint64_t(d.geometry.type));
        hs(d.geometry.circle.center);
        hs(d.geometry.circle.radius);
        hs(std::uint64_t(d.geometry.polygon.count));
        for (int k = 0; k < d.geometry.polygon.count; ++k)
            hs(d.geometry.polygon.vertices[std::size_t(k)]);
        hs(d.material.density);
        hs(d.material.restitution);
        hs(d.material.friction);
    }
    hs(std::uint64_t(w.contacts.size()));
    for (std::size_t i = 0; i < w.contacts.size(); ++i) {
        const Contact& c = w.contacts[i];
        hs(std::uint64_t(c.shape_a) << 32 | c.shape_b);
        hs(std::uint64_t(c.manifold.count));
        for (int j = 0; j < c.manifold.count; ++j) {
            hs(c.manifold.points[j].point);
            hs(c.manifold.points[j].separation);
            hs(w.warm_impulses[i].normal[j]);
            hs(w.warm_impulses[i].tangent[j]);
        }
    }
    return hs.h;
}

} // namespace tamias2d
