// A snapshot that is not one, of another format, cut short or changed is refused with a
// SnapshotError naming the byte offset, the field and the rule, and the world it was to be
// restored into is left exactly as it was (World::restore's strong guarantee).
//
// Oracle: the world's own state_hash() and snapshot() before the refused call (bitwise the
// same after it), and the corruptions themselves: every single-bit flip of a snapshot changes
// its checksum (XXH64, computed here by the xxHash project's own library: a one-bit change
// leaves it equal with probability 2^-64), every truncation its length. A
// guarantee of the library's API, not an SRS item: the `reliability` tag.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <random>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "fuzz/fuzz_support.hpp"
#include "snapshot/snapshot_worlds.hpp"
#include "support/reference_xxh64.hpp"
#include "tamias2d/world.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;
using namespace snapshot_test;

namespace {

/// A snapshot of a random world after some steps: contacts, joints, sensors, free slots.
std::vector<std::byte> some_snapshot(std::uint64_t seed, int steps) {
    World w = random_world(seed);
    for (int s = 0; s < steps; ++s)
        w.step(1.0 / 60.0);
    return w.snapshot();
}

/// Whether restoring `bytes` into `target` is refused with a SnapshotError whose field starts
/// with `field` (any field when empty) and leaves `target` bitwise as it was.
bool refused_unchanged(World& target, std::span<const std::byte> bytes,
                       const std::string& field = "") {
    const std::uint64_t hash = target.state_hash();
    const std::vector<std::byte> before = target.snapshot();
    try {
        target.restore(bytes);
    } catch (const SnapshotError& e) {
        BOOST_TEST_INFO(e.what());
        BOOST_TEST(e.field.rfind(field, 0) == 0);
        BOOST_TEST(std::string(e.what()).find(e.field) != std::string::npos);
        return target.state_hash() == hash && target.snapshot() == before;
    }
    return false;
}

/// A static ground body (no shape) and two dynamic discs of radius 0.25 m at (1, 0) and (2, 0).
struct TwoDiscs {
    BodyId ground, a, b;
};
TwoDiscs two_discs(World& w) {
    const BodyId ground = w.create_body({.type = BodyType::static_body});
    const BodyId a = w.create_body({.position = {1.0, 0.0}});
    const BodyId b = w.create_body({.position = {2.0, 0.0}});
    w.create_shape(a, circle_shape(0.25));
    w.create_shape(b, circle_shape(0.25));
    return {ground, a, b};
}

/// The snapshot's checksum (its header's first 24 bytes, then the payload) made right again,
/// so that a change reaches the reader of the sections.
void fix_checksum(std::vector<std::byte>& b) {
    const std::span<const std::byte> all(b);
    const std::uint64_t h = tamias_test::reference_xxh64(
        all.subspan(32), tamias_test::reference_xxh64(all.first(24), 0));
    for (int k = 0; k < 8; ++k)
        b[24 + std::size_t(k)] = std::byte(h >> (8 * k));
}

/// A double's bytes as a snapshot holds them (the host's order, as the checks here read them).
std::vector<std::byte> bytes(double v) {
    std::vector<std::byte> out(sizeof v);
    std::memcpy(out.data(), &v, sizeof v);
    return out;
}

void put_u32(std::vector<std::byte>& b, std::size_t at, std::uint32_t v) {
    for (int k = 0; k < 4; ++k)
        b[at + std::size_t(k)] = std::byte(v >> (8 * k));
}

/// The u32 at byte k of a snapshot (little-endian, as the format writes it).
std::uint32_t u32_in(const std::vector<std::byte>& b, std::size_t k) {
    std::uint32_t v = 0;
    for (int i = 0; i < 4; ++i)
        v |= std::uint32_t(b[k + std::size_t(i)]) << (8 * i);
    return v;
}

/// The error of World::from_snapshot on `forged`, after checking that a world restoring it
/// refuses it too, unchanged, naming a field under `record`; none if it was accepted.
std::optional<SnapshotError> refusal(const std::vector<std::byte>& forged,
                                     const std::string& record) {
    World target;
    BOOST_TEST(refused_unchanged(target, forged, record));
    try {
        World::from_snapshot(forged);
    } catch (const SnapshotError& e) {
        return e;
    }
    return std::nullopt;
}

/// Where the section tagged `tag` starts in `b` and where the next section (any of the tags
/// the writer uses) starts after it: the section's bytes.
std::pair<std::size_t, std::size_t> section_bytes(const std::vector<std::byte>& b,
                                                  const std::string& tag) {
    const auto find = [&](const std::string& t, std::size_t from) {
        const auto it = std::search(b.begin() + std::ptrdiff_t(from), b.end(), t.begin(), t.end(),
                                    [](std::byte x, char c) { return char(x) == c; });
        return std::size_t(it - b.begin());
    };
    const std::size_t begin = find(tag, 32);
    std::size_t end = b.size();
    for (const char* next : {"WRLD", "BODY", "SHAP", "BRPH", "CONT", "SENS", "JOIN", "EVNT"})
        if (next != tag)
            end = std::min(end, find(next, begin + 4));
    return {begin, end};
}

/// `b` with the first bytes of the double `from` in the section tagged `tag` made those of `to`
/// (a value found by its bytes: one no other field of the section holds), its checksum made
/// right again.
std::vector<std::byte> with_double(std::vector<std::byte> b, const std::string& tag, double from,
                                   double to) {
    const auto [begin, end] = section_bytes(b, tag);
    const std::vector<std::byte> f = bytes(from), t = bytes(to);
    const auto at = std::search(b.begin() + std::ptrdiff_t(begin), b.begin() + std::ptrdiff_t(end),
                                f.begin(), f.end());
    BOOST_TEST_REQUIRE((at != b.begin() + std::ptrdiff_t(end)), tag << ": " << from << " found");
    std::copy(t.begin(), t.end(), at);
    fix_checksum(b);
    return b;
}

/// A disc of radius 0.5 alone in a world without gravity: its mass, pi / 4 kg, and its moment
/// of inertia, pi / 32 kg m^2, are values no other field of its body's section holds.
struct LoneDisc {
    World world{WorldDef{.gravity = {0.0, 0.0}}};
    BodyId disc = world.create_body(BodyDef{});
    LoneDisc() { world.create_shape(disc, circle_shape(0.5)); }
};

/// `b` with the body section's double `from` made `to`, and its inverse 1 / from made 1 / to
/// (the reader asks that a mass property and its inverse agree).
std::vector<std::byte> with_value_and_inverse(const std::vector<std::byte>& b, double from,
                                              double to) {
    return with_double(with_double(b, "BODY", from, to), "BODY", 1.0 / from, 1.0 / to);
}

} // namespace

BOOST_AUTO_TEST_SUITE(snapshot_refusal)

// Oracle: World::restore's documented strong guarantee (world.hpp): a changed snapshot is
// refused with SnapshotError, the world's state_hash() and snapshot() bytes as before the call.
// Every bit of the header, then seeded bits anywhere, each flip breaking a header field or the
// XXH64 checksum; the intact snapshot is then accepted (positive control).
BOOST_AUTO_TEST_CASE(a_flipped_bit_is_refused, *utf::label("reliability")) {
    const std::vector<std::byte> good = some_snapshot(3, 40);
    World target = random_world(8);
    target.step(0.01);
    std::mt19937_64 r(1);
    for (int k = 0; k < 400; ++k) {
        // Every bit of the 32-byte header, then bits anywhere.
        const std::size_t bit = k < 256 ? std::size_t(k) : std::size_t(r() % (8 * good.size()));
        std::vector<std::byte> bad = good;
        bad[bit / 8] ^= std::byte(1u << (bit % 8));
        BOOST_TEST_INFO("bit " << bit % 8 << " of byte " << bit / 8 << " flipped");
        BOOST_TEST(refused_unchanged(target, bad));
    }
    // The good one is accepted (the refusals above were the corruption's).
    target.restore(good);
    BOOST_TEST((target.snapshot() == good));
}

// Oracle: World::restore's documented strong guarantee (world.hpp): a truncated snapshot, or
// one a byte too long, is refused with SnapshotError naming "header" (cut inside the 32-byte
// header) or "header.payload_size", the world's state_hash() and snapshot() bytes unchanged.
BOOST_AUTO_TEST_CASE(a_truncated_snapshot_is_refused, *utf::label("reliability")) {
    const std::vector<std::byte> good = some_snapshot(5, 30);
    World target = random_world(6);
    std::mt19937_64 r(2);
    for (int k = 0; k < 300; ++k) {
        const std::size_t n = k < 64 ? std::size_t(k) : std::size_t(r() % good.size());
        BOOST_TEST_INFO("cut to " << n << " of " << good.size() << " bytes");
        BOOST_TEST(refused_unchanged(target, std::span(good).first(n),
                                     n < 32 ? "header" : "header.payload_size"));
    }
    std::vector<std::byte> longer = good;
    longer.push_back(std::byte{0});
    BOOST_TEST(refused_unchanged(target, longer, "header.payload_size"));
}

// Oracle: the documented refusals of restore and from_snapshot (world.hpp), the strong
// guarantee read from state_hash() and snapshot(): JSON text and random noise fail the magic; a
// real snapshot given the next format version, its checksum made right by the xxHash project's
// own XXH64, fails the version; workers = 0 is a ValidationError.
BOOST_AUTO_TEST_CASE(a_foreign_snapshot_is_refused, *utf::label("reliability")) {
    World target = random_world(7);
    const std::string json = R"({"world": {"gravity": [0, -9.81]}, "bodies": []})";
    std::vector<std::byte> text(json.size());
    for (std::size_t k = 0; k < json.size(); ++k)
        text[k] = std::byte(json[k]);
    BOOST_TEST(refused_unchanged(target, text, "header.magic"));
    std::mt19937_64 r(3);
    std::vector<std::byte> noise(4096);
    for (std::byte& b : noise)
        b = std::byte(r());
    BOOST_TEST(refused_unchanged(target, noise, "header.magic"));
    // Another format version, with a checksum made for it: refused for the version.
    std::vector<std::byte> future = some_snapshot(9, 5);
    put_u32(future, 8, World::snapshot_format_version + 1);
    fix_checksum(future);
    BOOST_TEST(refused_unchanged(target, future, "header.format_version"));
    BOOST_CHECK_THROW(World::from_snapshot(noise), SnapshotError);
    BOOST_CHECK_THROW(World::from_snapshot(some_snapshot(9, 5), 0), ValidationError);
}

// Oracle: the documented contract of from_snapshot and restore (world.hpp): an inconsistent
// snapshot is refused with SnapshotError, the target world unchanged (state_hash() and
// snapshot() bytes), or the world read from it steps or refuses its step, never reading out of
// bounds (judged by the ASan/UBSan build). The changes sit behind a checksum made right again
// by the xxHash project's own XXH64 (as a forged or buggy writer would make them), so only the
// sections' checks of every count, index, flag and link can catch them; some must be refused.
// Seeded (random bytes, 0xFF, zeroed runs); TAMIAS_FUZZ_ITERATIONS and TAMIAS_FUZZ_SEED run
// more or others.
BOOST_AUTO_TEST_CASE(a_forged_snapshot_is_refused_or_read_safely, *utf::label("reliability")) {
    const long n = fuzz::iterations("TAMIAS_FUZZ_ITERATIONS", 600);
    const std::uint64_t seed = fuzz::base_seed(4);
    const std::vector<std::byte> good = some_snapshot(11 + seed, 60);
    World target = random_world(12);
    std::mt19937_64 r(seed);
    int refused = 0;
    for (long k = 0; k < n; ++k) {
        std::vector<std::byte> bad = good;
        const std::size_t at = 32 + std::size_t(r() % (bad.size() - 32));
        const int kind = int(k % 3);
        const std::size_t run = kind == 2 ? 1 + std::size_t(r() % 16) : 1;
        for (std::size_t j = at; j < at + run && j < bad.size(); ++j)
            bad[j] = kind == 0 ? std::byte(r()) : kind == 1 ? std::byte{0xFF} : std::byte{0};
        fix_checksum(bad);
        const std::uint64_t hash = target.state_hash();
        try {
            World w = World::from_snapshot(bad);
            for (int s = 0; s < 3; ++s)
                w.step(1.0 / 60.0);
        } catch (const SnapshotError&) {
            ++refused;
            BOOST_TEST(refused_unchanged(target, bad));
        } catch (const std::exception&) { // a state the step refuses (ValidationError, ...)
        }
        BOOST_TEST(target.state_hash() == hash);
    }
    BOOST_TEST_MESSAGE(refused << " of " << n
                               << " forged snapshots refused by the sections' reader");
    BOOST_TEST(refused > 0);
}

// Oracle: the documented contract of from_snapshot (world.hpp) and the property that a read
// never leaves its arrays: every byte of every section forged in turn (1 at even offsets, 0xFF
// at odd ones; the checksum made right by the xxHash project's own XXH64), the reader refuses
// the snapshot, or the world it reads steps (or refuses the step). The sanitizer build
// (scripts/test.sh --sanitize) judges the reads; every build, that nothing crashes and that an
// accepted world's bodies stay finite. The standard library's debug assertions (the coverage
// build's _GLIBCXX_ASSERTIONS) judge the preconditions: a joint's impulse bounds forged negative
// would cross a clamp's bounds.
BOOST_AUTO_TEST_CASE(every_byte_of_every_section_forged, *utf::label("reliability")) {
    const std::vector<std::byte> good = some_snapshot(11 + fuzz::base_seed(4), 60);
    const auto [joints_begin, joints_end] = section_bytes(good, "JOIN");
    BOOST_TEST_REQUIRE(joints_end - joints_begin > 1000u); // joints, some destroyed
    int refused = 0, stepped = 0;
    for (std::size_t at = 32; at < good.size(); ++at) {
        const std::byte value = at % 2 == 0 ? std::byte{1} : std::byte{0xFF};
        if (good[at] == value)
            continue;
        std::vector<std::byte> bad = good;
        bad[at] = value;
        fix_checksum(bad);
        try {
            World w = World::from_snapshot(bad);
            w.step(1.0 / 60.0);
            for (const BodyId body : w.bodies())
                BOOST_TEST(std::isfinite(w.position(body).x), "byte " << at);
            ++stepped;
        } catch (const SnapshotError&) {
            ++refused;
        } catch (const std::exception&) { // a state the step refuses (ValidationError, ...)
        }
    }
    BOOST_TEST_MESSAGE(refused << " refused, " << stepped << " stepped of " << good.size() - 32
                               << " forged bytes");
    BOOST_TEST(refused > 0);
}

// A joint's impulse bounds forged negative (the motor's torque, a motor joint's torque and
// force): the reader refuses them, naming the field, where the solve would clamp an impulse
// between crossed bounds (std::clamp's precondition; the coverage build's debug assertions
// aborted on the every-byte test above). Oracle: the definitions' own rule, each bound >= 0.
BOOST_AUTO_TEST_CASE(a_joints_impulse_bound_forged_negative_is_refused,
                     *utf::label("reliability")) {
    World w;
    const auto [ground, a, b] = two_discs(w);
    RevoluteJointDef rj{.body_a = ground, .body_b = a, .anchor = {0.0, 0.0}};
    rj.enable_motor = true;
    rj.max_motor_torque = 3.0625; // (values no other field holds: found by their bytes)
    w.create_joint(rj);
    MotorJointDef mj{.body_a = a, .body_b = b};
    mj.max_torque = 5.1875;
    mj.max_force = 7.3125;
    w.create_joint(mj);
    w.step(1.0 / 60.0);
    const std::vector<std::byte> good = w.snapshot();
    for (const auto& [field, value] :
         {std::pair{"max_motor", 3.0625}, {"max_torque", 5.1875}, {"max_force", 7.3125}}) {
        const std::vector<std::byte> forged = with_double(good, "JOIN", value, -value);
        World target;
        BOOST_TEST(refused_unchanged(target, forged, std::string("joints[")), field);
        try {
            World::from_snapshot(forged);
            BOOST_TEST(false, field << ": accepted");
        } catch (const SnapshotError& e) {
            BOOST_TEST(std::string(e.what()).find(field) != std::string::npos, e.what());
        }
    }
}

// A live joint whose body_a or body_b is forged to the body slot count (one past the last
// body) is refused at its record, naming the joint, where the solve would read a body past the
// array. Oracle: the reader's rule, "a live joint's bodies must live" (a body index below the
// slot count, of a live body), at its boundary; and the format's record order (type,
// collide_connected, then body_a and body_b just before the local anchors), the local anchor's
// value, which no other field holds, finding them.
BOOST_AUTO_TEST_CASE(a_joint_naming_the_body_past_the_last_is_refused, *utf::label("reliability")) {
    World w;
    const TwoDiscs discs = two_discs(w);
    const BodyId a = discs.a, b = discs.b;
    w.create_joint(RevoluteJointDef{.body_a = a, .body_b = b, .anchor = {1.40625, 0.0}});
    w.step(1.0 / 60.0);
    const std::vector<std::byte> good = w.snapshot();
    const auto [begin, end] = section_bytes(good, "JOIN");
    const std::vector<std::byte> anchor = bytes(0.40625); // local_anchor_a.x
    const auto it = std::search(good.begin() + std::ptrdiff_t(begin),
                                good.begin() + std::ptrdiff_t(end), anchor.begin(), anchor.end());
    BOOST_TEST_REQUIRE((it != good.begin() + std::ptrdiff_t(end)));
    const std::size_t anchor_at = std::size_t(it - good.begin());
    const std::size_t body_a = anchor_at - 8, body_b = anchor_at - 4;
    BOOST_TEST_REQUIRE(u32_in(good, body_a) == a.index);
    BOOST_TEST_REQUIRE(u32_in(good, body_b) == b.index);
    for (const std::size_t at : {body_a, body_b}) {
        std::vector<std::byte> forged = good;
        put_u32(forged, at, 3); // the body slot count
        fix_checksum(forged);
        const std::optional<SnapshotError> e = refusal(forged, "joints[0]");
        BOOST_TEST_REQUIRE(e.has_value(), (at == body_a ? "body_a" : "body_b") << " accepted");
        BOOST_TEST(e->field == "joints[0].body_a", e->what());
        BOOST_TEST(e->offset < body_a, e->what()); // the record's start, before its bodies
    }
    BOOST_TEST((World::from_snapshot(good).snapshot() == good)); // the intact one is read
}

// A list of move-event flags one shorter than the bodies (its count lowered, the last flag's
// byte taken out, the header's payload size and checksum made right) is refused at its count,
// naming it: every world keeps one flag per body slot, and a step reads the flag of each.
// Oracle: the reader's rule; and the format's tail (the flags' count, a byte per flag, then
// thresholds_used: the last 12 bytes for 3 bodies), checked on the good snapshot first.
BOOST_AUTO_TEST_CASE(a_move_flag_list_shorter_than_the_bodies_is_refused,
                     *utf::label("reliability")) {
    World w;
    BodyDef d;
    d.enable_move_events = true;
    w.create_body(d);
    d.enable_move_events = false;
    w.create_body(d);
    w.create_body(d);
    w.step(1.0 / 60.0);
    const std::vector<std::byte> good = w.snapshot();
    const std::size_t count_at = good.size() - 12;
    BOOST_TEST_REQUIRE(u32_in(good, count_at) == 3u);
    BOOST_TEST_REQUIRE(u32_in(good, count_at + 4) == 0u);
    BOOST_TEST_REQUIRE(std::to_integer<int>(good[count_at + 8]) == 1);  // body 0's flag
    BOOST_TEST_REQUIRE(std::to_integer<int>(good[count_at + 10]) == 0); // body 2's
    std::vector<std::byte> forged = good;
    put_u32(forged, count_at, 2);
    forged.erase(forged.begin() + std::ptrdiff_t(count_at + 10));
    put_u32(forged, 16, u32_in(good, 16) - 1); // the payload size (below 2^32)
    fix_checksum(forged);
    const std::optional<SnapshotError> e = refusal(forged, "move_flags");
    BOOST_TEST_REQUIRE(e.has_value(), "accepted");
    BOOST_TEST(e->offset == count_at, e->what());
    BOOST_TEST(e->field == "move_flags", e->what());
    BOOST_TEST((World::from_snapshot(good).snapshot() == good)); // the intact one is read
}

// A record count forged beyond what the bytes left can hold (the broad phase's first tree's
// node count, set to the number of bytes left after it) is refused by its own rule, before any
// record is read or allocated, not later as a cut-short snapshot. Oracle: SnapshotError's
// documented rule, "a count beyond the bytes left" (snapshot_error.hpp), and the node's size:
// a node holds at least its box, four doubles, so a count of one node per byte left cannot fit.
// The count's place, the section tag then two doubles (margin, least margin), is the format's.
BOOST_AUTO_TEST_CASE(a_count_beyond_the_bytes_left_is_refused_as_such, *utf::label("reliability")) {
    const std::vector<std::byte> good = some_snapshot(5, 20);
    const std::size_t at = section_bytes(good, "BRPH").first + 4 + 2 * sizeof(double);
    const std::uint64_t left = good.size() - (at + 8);
    std::vector<std::byte> forged = good;
    for (int k = 0; k < 8; ++k)
        forged[at + std::size_t(k)] = std::byte(left >> (8 * k));
    fix_checksum(forged);
    World target = random_world(6);
    BOOST_TEST(refused_unchanged(target, forged, ""));
    try {
        World::from_snapshot(forged);
        BOOST_TEST(false, "accepted");
    } catch (const SnapshotError& e) {
        BOOST_TEST(e.offset == at, e.what());
        BOOST_TEST(e.field.ends_with("nodes"), e.what());
        BOOST_TEST(e.rule.starts_with("must fit in the " + std::to_string(left) + " bytes left"),
                   e.what());
    }
}

// A dynamic body's mass is read as any positive finite value: the smallest positive normal
// double is accepted (its inverse, finite, written to match), and zero of either sign is
// refused, naming the field, though its inverse is written to match too (1 / 0: infinite).
// Oracle: the rule of the mass properties as update_mass leaves them (body_store.cpp's reader:
// a dynamic body's mass > 0 and finite, the inverses its own; R2: a dynamic body has a positive
// mass), the boundary on each side. The fields are found by their bytes (LoneDisc).
BOOST_AUTO_TEST_CASE(a_dynamic_bodys_mass_of_zero_is_refused, *utf::label("reliability")) {
    LoneDisc lone;
    const double mass = lone.world.mass(lone.disc);
    const std::vector<std::byte> good = lone.world.snapshot();
    const auto forged = [&](double to) { return with_value_and_inverse(good, mass, to); };
    const double smallest = std::numeric_limits<double>::min();
    World loaded = World::from_snapshot(forged(smallest));
    for (const BodyId b : loaded.bodies())
        BOOST_TEST(loaded.mass(b) == smallest);
    for (const double zero : {0.0, -0.0}) {
        try {
            World::from_snapshot(forged(zero));
            BOOST_TEST(false, "a mass of " << zero << " accepted");
        } catch (const SnapshotError& e) {
            BOOST_TEST(e.field.ends_with("mass"), e.what());
        }
    }
}

/// The lone disc's snapshot with the field holding `value` (and its inverse, written to match)
/// forged to the largest finite double, then to infinity: the first is read, `read` gives it
/// back and a step leaves the velocities finite; the second is refused naming `field`.
template <class Read>
void read_up_to_the_largest_finite_value(double value, Read read, const std::string& field) {
    LoneDisc lone;
    const std::vector<std::byte> good = lone.world.snapshot();
    const auto forged = [&](double to) { return with_value_and_inverse(good, value, to); };
    const double largest = std::numeric_limits<double>::max();
    World loaded = World::from_snapshot(forged(largest));
    for (const BodyId b : loaded.bodies()) { // the one body, by the new world's handle
        BOOST_TEST(read(loaded, b) == largest);
        loaded.step(1.0 / 60.0);
        BOOST_TEST(std::isfinite(loaded.velocity(b).x));
        BOOST_TEST(std::isfinite(loaded.velocity(b).y));
        BOOST_TEST(std::isfinite(loaded.angular_velocity(b)));
    }
    try {
        World::from_snapshot(forged(std::numeric_limits<double>::infinity()));
        BOOST_TEST(false, "an infinite " << field << " accepted");
    } catch (const SnapshotError& e) {
        BOOST_TEST(e.field.ends_with(field), e.what());
    }
}

// A dynamic body's mass is read up to the largest finite double (its inverse a subnormal) and
// stepped to finite velocities; infinity is refused, naming the field. Oracle: the rule of the
// mass properties as update_mass leaves them (body_store.cpp's reader: a dynamic body's mass
// > 0 and finite, the inverses its own), the upper boundary on each side. The fields are found
// by their bytes (LoneDisc).
BOOST_AUTO_TEST_CASE(a_dynamic_bodys_mass_is_read_up_to_the_largest_finite_value,
                     *utf::label("reliability")) {
    LoneDisc lone;
    read_up_to_the_largest_finite_value(
        lone.world.mass(lone.disc), [](const World& w, BodyId b) { return w.mass(b); }, "mass");
}

// A body's moment of inertia is read as any finite non-negative value: the largest finite
// double is accepted (its inverse written to match), and infinity is refused, naming the field.
// Oracle: the rule of the mass properties as update_mass leaves them (body_store.cpp's reader:
// a dynamic body's inertia finite and >= 0, the inverses its own), the boundary on each side.
// The fields are found by their bytes (LoneDisc: I = m r^2 / 2 = pi / 32 kg m^2).
BOOST_AUTO_TEST_CASE(a_bodys_inertia_is_read_up_to_the_largest_finite_value,
                     *utf::label("reliability")) {
    LoneDisc lone;
    read_up_to_the_largest_finite_value(
        lone.world.inertia(lone.disc), [](const World& w, BodyId b) { return w.inertia(b); },
        "inertia");
}

// A body's rotation (cos, sin) forged off unit length is refused, naming xf: a rotation that
// is not one would scale the body's shapes. Oracle: the reader's rule (body_store.cpp's
// unsupported_field: c^2 + s^2 within 1e-6 of 1) on each side of its bound: off by 1.5e-6,
// refused; off by 0.5e-6, read. The rotation's cosine is found by its bytes: a body at 0.5 rad
// alone in its world, cos 0.5 a value no other field holds.
BOOST_AUTO_TEST_CASE(a_bodys_rotation_off_unit_length_is_refused, *utf::label("reliability")) {
    World w(WorldDef{.gravity = {0.0, 0.0}});
    w.create_shape(w.create_body(BodyDef{.angle = 0.5}), circle_shape(0.5));
    const std::vector<std::byte> good = w.snapshot();
    const auto forged = [&](double off) {
        const double s = std::sin(0.5);
        return with_double(good, "BODY", std::cos(0.5), std::sqrt(1.0 + off - s * s));
    };
    const std::optional<SnapshotError> e = refusal(forged(1.5e-6), "bodies[0]");
    BOOST_TEST_REQUIRE(e.has_value(), "a rotation 1.5e-6 off unit accepted");
    BOOST_TEST(e->field == "bodies[0].xf", e->what());
    BOOST_TEST(World::from_snapshot(forged(0.5e-6)).bodies().size() == 1u);
}

// A body's time at rest forged infinite is refused, naming sleep_time: a step adds to it and
// compares it with time_to_sleep, and an infinite one would put the body to sleep at once.
// Oracle: the reader's rule (body_store.cpp's unsupported_field: 0 <= sleep_time < inf) at its
// upper end; the largest finite value is read. The field is found by its bytes: a body at rest
// for 5 steps of 1/64 s in a world with sleeping has rested 5/64 s, a value no other field holds.
BOOST_AUTO_TEST_CASE(a_bodys_time_at_rest_forged_infinite_is_refused, *utf::label("reliability")) {
    World w(WorldDef{.gravity = {0.0, 0.0}, .enable_sleep = true});
    w.create_shape(w.create_body(BodyDef{}), circle_shape(0.5));
    for (int k = 0; k < 5; ++k)
        w.step(1.0 / 64.0);
    const std::vector<std::byte> good = w.snapshot();
    const auto forged = [&](double to) { return with_double(good, "BODY", 5.0 / 64.0, to); };
    const std::optional<SnapshotError> e =
        refusal(forged(std::numeric_limits<double>::infinity()), "bodies[0]");
    BOOST_TEST_REQUIRE(e.has_value(), "an infinite time at rest accepted");
    BOOST_TEST(e->field == "bodies[0].sleep_time", e->what());
    BOOST_TEST(World::from_snapshot(forged(std::numeric_limits<double>::max())).bodies().size() ==
               1u);
}

// Oracle: SnapshotReader's rule for a section's tag: a payload whose section tag is not the one
// the reader expects there is refused at the tag's offset, naming "section" and the tag it
// must be, the world unchanged. Each of the eight sections' tags, one letter changed, with the
// checksum made right again.
BOOST_AUTO_TEST_CASE(a_wrong_section_tag_is_refused_naming_the_tag, *utf::label("reliability")) {
    const std::vector<std::byte> good = some_snapshot(3, 40);
    World target = random_world(8);
    for (const char* tag : {"WRLD", "BODY", "SHAP", "BRPH", "CONT", "SENS", "JOIN", "EVNT"}) {
        const std::size_t at = section_bytes(good, tag).first;
        BOOST_TEST_REQUIRE(at < good.size(), tag);
        std::vector<std::byte> bad = good;
        bad[at + 3] = std::byte('?');
        fix_checksum(bad);
        BOOST_TEST(refused_unchanged(target, bad, ""), tag);
        try {
            World::from_snapshot(bad);
            BOOST_TEST(false, tag << ": accepted");
        } catch (const SnapshotError& e) {
            BOOST_TEST(e.offset == at, e.what());
            BOOST_TEST(e.field == "section", e.what());
            BOOST_TEST(e.rule == "must be the section '" + std::string(tag) + "'", e.what());
        }
    }
}

// A contact naming its second shape by the shape count, one past the last shape, is refused at
// its record, naming the record by its index and shape_a's rule, before any shape is read by
// that index. Oracle: the contact's documented rule (contact_manager.cpp's reader: two live
// shapes, shape_a < shape_b, of the bodies named) and the world's three shapes: the ground
// (0) and two boxes resting on it apart (1, 2), so two contacts, (0, 1) then (0, 2). A record
// starts with shape_a then shape_b (the format's); the first follows the section's tag and
// count, the second is found by its two shapes after it; the bodies follow the shapes.
BOOST_AUTO_TEST_CASE(a_contact_naming_the_shape_past_the_last_is_refused,
                     *utf::label("reliability")) {
    World w;
    const BodyId ground = w.create_body({.type = BodyType::static_body});
    w.create_shape(ground, box_shape(10.0, 1.0));
    for (const double x : {-2.0, 2.0})
        w.create_shape(w.create_body({.position = {x, 0.99}}), box_shape(1.0, 1.0));
    w.step(1.0 / 60.0);
    const std::vector<std::byte> good = w.snapshot();
    const auto u32_at = [&](std::size_t k) { return u32_in(good, k); };
    const auto [begin, end] = section_bytes(good, "CONT");
    std::size_t records[2] = {begin + 4 + 8, 0};
    for (std::size_t k = records[0] + 8; k + 8 <= end && records[1] == 0; ++k)
        if (u32_at(k) == 0u && u32_at(k + 4) == 2u)
            records[1] = k;
    for (std::uint32_t i = 0; i < 2; ++i) {
        const std::size_t at = records[i];
        BOOST_TEST_REQUIRE(at != 0u, "contact " << i << " found");
        BOOST_TEST_REQUIRE(u32_at(at) == 0u, "shape_a of contact " << i);
        BOOST_TEST_REQUIRE(u32_at(at + 4) == i + 1, "shape_b of contact " << i);
        std::vector<std::byte> forged = good;
        put_u32(forged, at + 4, 3); // the shape count
        fix_checksum(forged);
        const std::string record = "contacts[" + std::to_string(i) + "]";
        const std::optional<SnapshotError> e = refusal(forged, record);
        BOOST_TEST_REQUIRE(e.has_value(), record << " accepted");
        BOOST_TEST(e->offset == at, e->what());
        BOOST_TEST(e->field == record + ".shape_a", e->what());
    }
    // A contact of the ground with itself (shape_b and body_b made shape_a's and body_a's):
    // refused by the rule's shape_a < shape_b, though each shape and body it names is live and
    // its own.
    BOOST_TEST_REQUIRE(u32_at(records[0] + 8) == 0u, "body_a of contact 0: the ground");
    BOOST_TEST_REQUIRE(u32_at(records[0] + 12) == 1u, "body_b of contact 0: the first box");
    std::vector<std::byte> self = good;
    put_u32(self, records[0] + 4, 0);  // shape_b: the ground's shape
    put_u32(self, records[0] + 12, 0); // body_b: the ground
    fix_checksum(self);
    const std::optional<SnapshotError> e = refusal(self, "contacts[0]");
    BOOST_TEST_REQUIRE(e.has_value(), "a contact of a shape with itself accepted");
    BOOST_TEST(e->field == "contacts[0].shape_a", e->what());
    BOOST_TEST((World::from_snapshot(good).snapshot() == good)); // the intact one is read
}

// A shape whose definition a forged snapshot breaks (a disc's radius made negative) is refused
// at its record's first byte, naming the record. Oracle: World::restore's documented refusal
// (the offset, the field, the rule) and the definitions' own rule (a radius > 0); the record
// starts with the geometry's type, then the disc's centre (two doubles) and radius (the
// format's), and the two discs' radii, values no other field holds, find them.
BOOST_AUTO_TEST_CASE(a_broken_shape_is_refused_at_its_record, *utf::label("reliability")) {
    World w;
    for (const double r : {0.3125, 0.4375})
        w.create_shape(w.create_body({.position = {4.0 * r, 0.0}}), circle_shape(r));
    const std::vector<std::byte> good = w.snapshot();
    const auto [begin, end] = section_bytes(good, "SHAP");
    std::size_t last = 0;
    for (const auto& [k, r] : {std::pair{0, 0.3125}, {1, 0.4375}}) {
        const std::vector<std::byte> from = bytes(r), to = bytes(-r);
        const auto found =
            std::search(good.begin() + std::ptrdiff_t(begin), good.begin() + std::ptrdiff_t(end),
                        from.begin(), from.end());
        BOOST_TEST_REQUIRE((found != good.begin() + std::ptrdiff_t(end)), "radius " << r);
        const auto radius_at = std::size_t(found - good.begin());
        const std::size_t record = radius_at - 2 * sizeof(double) - sizeof(ShapeType);
        std::vector<std::byte> forged = good;
        std::copy(to.begin(), to.end(), forged.begin() + std::ptrdiff_t(radius_at));
        fix_checksum(forged);
        const std::string name = "shapes[" + std::to_string(k) + "]";
        const std::optional<SnapshotError> e = refusal(forged, name);
        BOOST_TEST_REQUIRE(e.has_value(), name << " accepted");
        BOOST_TEST(e->offset == record, e->what());
        BOOST_TEST(e->field == name, e->what());
        BOOST_TEST(record > last); // the second record after the first
        last = record;
    }
}

// A live shape on no body's shape list, naming as its body one past the last, is refused,
// naming the shape's body field, before that body is looked up. Oracle: the snapshot's rule for
// the bodies' shape lists (body_store.cpp: a live shape must be on the shape list of a live
// body). Two bodies with a disc each; the second body's list is emptied and its disc made to
// name body 2. The fields are found by the second body's x, 7.8125 (no other field holds it):
// its record's first_shape is the u32 before its transform, and the disc's body is the u32
// after the disc's copy of that transform (four doubles) and of the body's centre (two).
BOOST_AUTO_TEST_CASE(a_shape_on_no_list_naming_a_body_past_the_last_is_refused,
                     *utf::label("reliability")) {
    World w;
    for (const double x : {1.0, 7.8125})
        w.create_shape(w.create_body({.position = {x, 0.0}}), circle_shape(0.25));
    const std::vector<std::byte> good = w.snapshot();
    const std::vector<std::byte> x = bytes(7.8125);
    const auto find_x = [&](const char* tag) {
        const auto [begin, end] = section_bytes(good, tag);
        const auto it = std::search(good.begin() + std::ptrdiff_t(begin),
                                    good.begin() + std::ptrdiff_t(end), x.begin(), x.end());
        BOOST_TEST_REQUIRE((it != good.begin() + std::ptrdiff_t(end)), tag);
        return std::size_t(it - good.begin());
    };
    const auto u32_at = [&](std::size_t k) { return u32_in(good, k); };
    const std::size_t first_shape = find_x("BODY") - 4;
    const std::size_t shape_body = find_x("SHAP") + 6 * sizeof(double);
    BOOST_TEST_REQUIRE(u32_at(first_shape) == 1u, "the second body's first shape");
    BOOST_TEST_REQUIRE(u32_at(shape_body) == 1u, "the second disc's body");
    std::vector<std::byte> forged = good;
    put_u32(forged, first_shape, 0xFFFFFFFFu); // no shape
    put_u32(forged, shape_body, 2);            // the body count
    fix_checksum(forged);
    const std::optional<SnapshotError> e = refusal(forged, "shapes[1]");
    BOOST_TEST_REQUIRE(e.has_value(), "accepted");
    BOOST_TEST(e->field == "shapes[1].body", e->what());
}

// A body whose shape list starts one past the last shape is refused, naming the body's
// first_shape, before any shape is looked up by that index. Oracle: the snapshot's rule for the
// bodies' shape lists (body_store.cpp: the list holds live shapes of this body, each once); the
// field is found as in the test above, by the second body's x.
BOOST_AUTO_TEST_CASE(a_shape_list_starting_past_the_last_shape_is_refused,
                     *utf::label("reliability")) {
    World w;
    for (const double x : {1.0, 7.8125})
        w.create_shape(w.create_body({.position = {x, 0.0}}), circle_shape(0.25));
    const std::vector<std::byte> good = w.snapshot();
    const std::vector<std::byte> x = bytes(7.8125);
    const auto [begin, end] = section_bytes(good, "BODY");
    const auto it = std::search(good.begin() + std::ptrdiff_t(begin),
                                good.begin() + std::ptrdiff_t(end), x.begin(), x.end());
    BOOST_TEST_REQUIRE((it != good.begin() + std::ptrdiff_t(end)), "the second body's x");
    const std::size_t first_shape = std::size_t(it - good.begin()) - 4;
    BOOST_TEST_REQUIRE(u32_in(good, first_shape) == 1u, "the second body's first shape");
    for (const std::uint32_t s : {2u, 3u}) { // the shape count, and one more
        std::vector<std::byte> forged = good;
        put_u32(forged, first_shape, s);
        fix_checksum(forged);
        const std::optional<SnapshotError> e = refusal(forged, "bodies[1]");
        BOOST_TEST_REQUIRE(e.has_value(), "first_shape " << s << " accepted");
        BOOST_TEST(e->field == "bodies[1].first_shape", e->what());
    }
}

namespace {
/// The offsets at which two snapshots of one length differ.
std::vector<std::size_t> differing_bytes(const std::vector<std::byte>& a,
                                         const std::vector<std::byte>& b) {
    BOOST_TEST_REQUIRE(a.size() == b.size());
    std::vector<std::size_t> out;
    for (std::size_t k = 32; k < a.size(); ++k) // past the header and its checksum
        if (a[k] != b[k])
            out.push_back(k);
    return out;
}
} // namespace

// Oracle: the sleep states a world holds (body_store.hpp, World::set_sleeping, set_enabled): a
// body is movable exactly when it is neither static nor disabled, only a movable body is awake,
// and with sleeping off every movable body is. A snapshot that breaks one is refused naming
// the body's field (the world unchanged, refused_unchanged); the flags are found by writing the
// same world in two states and comparing the bytes, so no offset is assumed.
BOOST_AUTO_TEST_CASE(a_sleep_state_no_world_holds_is_refused, *utf::label("reliability")) {
    const auto make = [](bool sleeping) {
        World w(WorldDef{.enable_sleep = sleeping});
        w.create_shape(w.create_body({.type = BodyType::static_body}), box_shape(4.0, 1.0));
        w.create_shape(w.create_body({.position = {0.0, 1.0}}), box_shape(1.0, 1.0));
        return w;
    };
    World awake = make(true), asleep = make(true), disabled = make(true);
    asleep.set_awake(asleep.bodies()[1], false);
    disabled.set_enabled(disabled.bodies()[1], false);
    // One byte tells a sleeping body from an awake one; a disabled body also differs in being
    // movable and disabled, after it.
    const std::vector<std::size_t> awake_flag =
        differing_bytes(awake.snapshot(), asleep.snapshot());
    BOOST_TEST_REQUIRE(awake_flag.size() == 1u);
    const std::vector<std::size_t> flags = differing_bytes(awake.snapshot(), disabled.snapshot());
    BOOST_TEST_REQUIRE(flags.size() == 3u);
    BOOST_TEST_REQUIRE(flags[0] == awake_flag[0]);
    const std::size_t movable_flag = flags[1];
    // The world's sleeping setting: the one byte two empty worlds differ in.
    const std::vector<std::size_t> setting =
        differing_bytes(World(WorldDef{.enable_sleep = true}).snapshot(),
                        World(WorldDef{.enable_sleep = false}).snapshot());
    BOOST_TEST_REQUIRE(setting.size() == 1u);

    struct Case {
        const World& from;
        std::size_t at;
        std::byte value;
        const char* field;
    };
    const Case cases[] = {
        {asleep, setting[0], std::byte{0}, "bodies[1].awake"},       // asleep with sleeping off
        {disabled, awake_flag[0], std::byte{1}, "bodies[1].awake"},  // awake, not movable
        {disabled, movable_flag, std::byte{1}, "bodies[1].movable"}, // movable and disabled
    };
    for (const Case& c : cases) {
        std::vector<std::byte> forged = c.from.snapshot();
        BOOST_TEST_REQUIRE((forged[c.at] != c.value), c.field);
        forged[c.at] = c.value;
        fix_checksum(forged);
        const std::optional<SnapshotError> e = refusal(forged, "bodies[1]");
        BOOST_TEST_REQUIRE(e.has_value(), "accepted: " << c.field);
        BOOST_TEST(e->field == c.field, e->what());
    }
    // The states themselves are read back (positive control).
    for (const World* w : {&awake, &asleep, &disabled})
        BOOST_TEST(World::from_snapshot(w->snapshot()).state_hash() == w->state_hash());
}

// Oracle: the edge input a contact's last narrow phase gives it (contact_manager.cpp,
// edge_input: its bodies, its path group, whether it touches, whether it bounces), which every
// world holds for each contact that has one, also where the step reads it without a narrow
// phase (a pair whose bodies sleep). A snapshot whose edge input differs from its contact's in
// any field is refused naming that field, before a step could read a body past the last. The
// fields are found by writing a box asleep on a floor twice, with restitution 0 and 0.5: the
// last byte the contacts section differs in is the edge input's bounces flag, after its
// bodies (u32 each), its path group and its touching flag.
BOOST_AUTO_TEST_CASE(an_edge_input_its_contact_does_not_give_is_refused,
                     *utf::label("reliability")) {
    const auto make = [](double restitution) {
        WorldDef def;
        def.enable_sleep = true;
        def.restitution_threshold = 1.0; // m/s: no resting contact bounces, so both sleep alike
        World w(def);
        w.create_shape(w.create_body({.type = BodyType::static_body}), box_shape(4.0, 1.0));
        const BodyId box = w.create_body({.position = {0.0, 1.0}});
        w.create_shape(box, box_shape(1.0, 1.0, Material{1.0, restitution, 0.5}));
        for (int s = 0; s < 200 && w.is_awake(box); ++s)
            w.step(1.0 / 60.0);
        BOOST_TEST_REQUIRE(!w.is_awake(box), "the box sleeps");
        return w.snapshot();
    };
    const std::vector<std::byte> still = make(0.0), bouncy = make(0.5);
    const auto [begin, end] = section_bytes(bouncy, "CONT");
    std::size_t bounces = 0;
    for (const std::size_t k : differing_bytes(still, bouncy))
        if (k >= begin && k < end)
            bounces = k;
    BOOST_TEST_REQUIRE(bounces != 0u);
    BOOST_TEST_REQUIRE((bouncy[bounces] == std::byte{1} && still[bounces] == std::byte{0}));
    const std::size_t body_a = bounces - 10, body_b = bounces - 6, touching = bounces - 1;
    BOOST_TEST_REQUIRE(u32_in(bouncy, body_a) == 0u, "the floor");
    BOOST_TEST_REQUIRE(u32_in(bouncy, body_b) == 1u, "the box");
    BOOST_TEST_REQUIRE((bouncy[touching] == std::byte{1}));
    struct Case {
        std::size_t at;
        std::uint32_t value; // a u32 at a body field, else a byte
        const char* field;
    };
    const Case cases[] = {
        {body_b, 2, "edge_inputs[0].body_b"},           // the body count: past the last
        {body_b, 0xFFFFFFFFu, "edge_inputs[0].body_b"}, // no body
        {body_a, 1, "edge_inputs[0].body_a"},           // a body, not the contact's
        {touching, 0, "edge_inputs[0].touching"},       {bounces, 0, "edge_inputs[0].bounces"},
    };
    for (const Case& c : cases) {
        std::vector<std::byte> forged = bouncy;
        if (c.at == body_a || c.at == body_b)
            put_u32(forged, c.at, c.value);
        else
            forged[c.at] = std::byte(c.value);
        fix_checksum(forged);
        const std::optional<SnapshotError> e = refusal(forged, "edge_inputs[0]");
        BOOST_TEST_REQUIRE(e.has_value(), "accepted: " << c.field << " = " << c.value);
        BOOST_TEST(e->field == c.field, e->what());
    }
    BOOST_TEST(World::from_snapshot(bouncy).snapshot() == bouncy); // the intact one is read
    // A contact begun while every body sleeps (a static shape put across the sleeping box) is
    // kept without a narrow phase: its edge input is its contact's too, and the world is read
    // back. (The contacts section starts with its tag and its count.)
    World w = World::from_snapshot(bouncy);
    w.create_shape(w.create_body({.type = BodyType::static_body, .position = {0.0, 1.25}}),
                   box_shape(0.5, 0.5));
    w.step(1.0 / 60.0);
    BOOST_TEST_REQUIRE(!w.is_awake(w.bodies()[1]), "the box still sleeps");
    const std::vector<std::byte> with_new = w.snapshot();
    BOOST_TEST_REQUIRE(u32_in(bouncy, begin + 4) == 1u);
    BOOST_TEST_REQUIRE(u32_in(with_new, section_bytes(with_new, "CONT").first + 4) == 2u);
    BOOST_TEST(World::from_snapshot(with_new).snapshot() == with_new);
}

// Oracle: the snapshot's rule for indices (SnapshotReader::index: an index is below its limit)
// at its boundary, on the bodies' free slots (slot_map.hpp: each must name a dead slot). Three
// bodies, the last destroyed: the section holds its tag, the slot count (u64), each slot's live
// flag and generation (5 bytes), the free count (u64) and the free slots (u32 each); the one
// free slot is made the slot count, then one more, and each is refused naming the field.
BOOST_AUTO_TEST_CASE(a_free_slot_naming_the_slot_count_is_refused, *utf::label("reliability")) {
    World w;
    std::vector<BodyId> bodies;
    for (int k = 0; k < 3; ++k)
        bodies.push_back(w.create_body({.position = {2.0 * k, 0.0}}));
    w.destroy_body(bodies[2]);
    const std::vector<std::byte> good = w.snapshot();
    const std::size_t begin = section_bytes(good, "BODY").first;
    const std::size_t free_count = begin + 4 + 8 + 3 * 5, free_slot = free_count + 8;
    BOOST_TEST_REQUIRE(u32_in(good, begin + 4) == 3u, "the slot count");
    BOOST_TEST_REQUIRE(u32_in(good, free_count) == 1u, "the free count");
    BOOST_TEST_REQUIRE(u32_in(good, free_slot) == 2u, "the free slot");
    for (const std::uint32_t slot : {3u, 4u}) {
        std::vector<std::byte> forged = good;
        put_u32(forged, free_slot, slot);
        fix_checksum(forged);
        const std::optional<SnapshotError> e = refusal(forged, "bodies");
        BOOST_TEST_REQUIRE(e.has_value(), "free slot " << slot << " accepted");
        BOOST_TEST(e->offset == free_slot, e->what());
        BOOST_TEST(e->field.find("free_slot") != std::string::npos, e->what());
    }
}

// A sensor's visitor list naming one shape twice is refused at the repeated entry. Oracle: the
// snapshot's rule for a sensor's visitors (sensor_overlaps.cpp: ascending shape indices, so each
// shape at most once, as DD28's set of overlapping shapes holds it); the list is found by its
// bytes: the count 2, then the two discs' shape indices 1 and 2 (the sensor's is 0).
BOOST_AUTO_TEST_CASE(a_sensor_visitor_named_twice_is_refused, *utf::label("reliability")) {
    World w(WorldDef{.gravity = {0.0, 0.0}});
    ShapeDef zone = box_shape(4.0, 4.0);
    zone.is_sensor = true;
    w.create_shape(w.create_body({.type = BodyType::static_body}), zone);
    for (const double x : {-1.0, 1.0})
        w.create_shape(w.create_body({.position = {x, 0.0}}), circle_shape(0.25));
    w.step(1.0 / 60.0);
    BOOST_TEST_REQUIRE(w.sensor_begin_events().size() == 2u);
    const std::vector<std::byte> good = w.snapshot();
    std::vector<std::byte> list(16);
    list[0] = std::byte{2};  // the visitor count, a u64
    list[8] = std::byte{1};  // the first visitor's shape index
    list[12] = std::byte{2}; // the second's
    const auto [begin, end] = section_bytes(good, "SENS");
    const auto it = std::search(good.begin() + std::ptrdiff_t(begin),
                                good.begin() + std::ptrdiff_t(end), list.begin(), list.end());
    BOOST_TEST_REQUIRE((it != good.begin() + std::ptrdiff_t(end)), "the visitor list found");
    std::vector<std::byte> forged = good;
    put_u32(forged, std::size_t(it - good.begin()) + 12, 1); // the first disc again
    fix_checksum(forged);
    const std::optional<SnapshotError> e = refusal(forged, "sensors[0]");
    BOOST_TEST_REQUIRE(e.has_value(), "accepted");
    BOOST_TEST(e->field == "sensors[0].visitor", e->what());
}

BOOST_AUTO_TEST_SUITE_END()
