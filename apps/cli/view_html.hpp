// The recorded run behind `tamias2d view`: geometry, joints and per-frame states of a scene,
// quantised and coded compactly, written as one self-contained HTML page (docs/viewer.md).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

#include "tamias2d/io/scene.hpp"
#include "tamias2d/world.hpp"

namespace tamias2d::cli {

/// Quantisation steps of the recorded states: the page shows positions and angles to four
/// decimals, velocities to three. Velocities in a pile jitter by far more than a step, so
/// each decimal less saves about 3 bits per value (docs/viewer.md).
inline constexpr double position_quantum = 1e-4;         ///< m
inline constexpr double angle_quantum = 1e-4;            ///< rad
inline constexpr double velocity_quantum = 1e-3;         ///< m s^-1
inline constexpr double angular_velocity_quantum = 1e-3; ///< rad s^-1
inline constexpr double contact_quantum = 1e-3;          ///< m, contact points (drawn only)

/// Appends signed integers as predictive residuals: each value is predicted from the same
/// body's two previous frames (linear extrapolation), and the residual is written as a zigzag
/// varint, runs of zero residuals as one token. Bodies at rest or in free flight cost about a
/// byte per value, or nothing within a run.
class ResidualStream {
  public:
    explicit ResidualStream(std::size_t bodies) : previous_(bodies), before_previous_(bodies) {}
    void add(std::size_t body, std::int64_t value); ///< the body's value in the current frame
    void end_frame() { ++frames_; }                 ///< after every body's add()
    std::vector<std::uint8_t> bytes() const;        ///< the stream so far, complete

  private:
    std::vector<std::int64_t> previous_;
    std::vector<std::int64_t> before_previous_;
    std::vector<std::uint8_t> bytes_;
    std::uint64_t zero_run_ = 0; ///< zero residuals not yet written
    int frames_ = 0;
};

/// A run recorded for the HTML player.
class Recording {
  public:
    struct Options {
        std::string title;                        ///< the scene's name in the page
        int every = 1;                            ///< steps between recorded frames
        std::size_t max_contact_points = 1000000; ///< over the run; past it, none are kept
    };

    /// Takes the shapes and joints from `scene` and the bodies' placement from `world` as
    /// io::build_world left it (`ids` in scene order), before any step.
    Recording(const io::Scene& scene, const World& world, std::vector<BodyId> ids, Options options);

    /// Records every body's state, the energy and the contact points after `step` steps.
    /// Throws std::runtime_error for a state that breaks SRS Table 2 (DCO_*), as `run` does.
    void add_frame(int step, const World& world);

    std::size_t frame_count() const { return steps_.size(); } ///< frames recorded so far

    /// Writes the player page: template, styles, script and this run's data.
    void write_html(std::ostream& out) const;

  private:
    struct Box {
        double min_x = 0.0, min_y = 0.0, max_x = 0.0, max_y = 0.0;
        bool empty = true;
        void add(double x, double y, double r);
    };

    std::string data_json() const;

    std::vector<BodyId> ids_;
    Options options_;
    std::vector<std::string> names_;
    std::vector<double> radius_; ///< m, farthest shape point from the centre of mass
    std::vector<double> unwrapped_angle_;
    std::vector<double> last_omega_;
    std::vector<ResidualStream> channels_; ///< x, y, phi, vx, vy, omega
    std::vector<int> steps_;
    std::vector<double> times_;
    std::vector<double> kinetic_;
    std::vector<double> potential_;
    std::vector<std::uint8_t> contacts_;
    /// The previous frame's contact points (x and y in steps, normal code): each point is
    /// coded against the one at its place there, which in a resting pile is the same point.
    std::vector<std::array<std::int64_t, 3>> last_contacts_;
    std::size_t contact_points_ = 0;
    bool contacts_dropped_ = false;
    std::size_t max_contacts_in_frame_ = 0;
    Box moving_bounds_; ///< m, of the bodies that are not static, over the run
    Box all_bounds_;
    std::string scene_json_; ///< the run's fixed part: bodies, shapes, joints, settings
};

} // namespace tamias2d::cli
