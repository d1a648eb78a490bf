#include "popup/simulation/simulate_fold.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

#include <tbb/parallel_for.h>

#include "body_graph.hpp"
#include "component_track.hpp"
#include "fold_solver.hpp"
#include "simulate_validated.hpp"

namespace popup {

namespace {

const std::string kWork = "the fold simulation"; // built once, not at every checkpoint

std::string degrees(double radians)
{
    std::ostringstream s;
    s.precision(4);
    s << radians * 180.0 / M_PI << "°";
    return s.str();
}

/// Ids of the moving patches of one component.
std::vector<int> component_patches(const Scaffold& s, const BodyGraph& g, int component)
{
    std::vector<int> ids;
    for (size_t i = 0; i < s.patches.size(); ++i) {
        const int b = g.body_of_patch[i];
        if (!g.is_base(b) && g.component_of_body[b] == component)
            ids.push_back(s.patches[i].id);
    }
    return ids;
}

/// " (patch 3 (name), patch 4)": the patches a message is about, for a person to read.
std::string patch_list(const Scaffold& s, const std::vector<int>& ids)
{
    std::ostringstream out;
    for (size_t k = 0; k < ids.size(); ++k) {
        const Patch& p = *s.find_patch(ids[k]);
        out << (k ? ", " : " (") << "patch " << p.id;
        if (!p.name.empty())
            out << " (" << p.name << ")";
    }
    out << (ids.empty() ? "" : ")");
    return out.str();
}

} // namespace

Loop3 posed_outline(const Patch& patch, const Pose& pose)
{
    Loop3 out;
    out.reserve(patch.outer.size());
    for (const Vec3& x : patch.outer)
        out.push_back(pose.apply(x));
    return out;
}

namespace {

struct Start {
    double angle;
    Configuration configuration;
    bool design; ///< the design state: flat folds there take their hinted branch
};

// Continuation of every component from `start` to each requested angle: closing runs first,
// then opening runs, each in travel order.
Result<FoldSweep> sweep_from(const Scaffold& s, const BodyGraph& g, const FoldSolver& solver,
                             const Start& start, const std::vector<double>& angles)
{
    stop_if_cancelled(solver.options().cancel, kWork);
    Result<FoldSweep> result;
    std::vector<int> order(angles.size());
    std::iota(order.begin(), order.end(), 0);
    std::vector<int> closing, opening;
    for (int i : order)
        (angles[i] <= start.angle ? closing : opening).push_back(i);
    std::sort(closing.begin(), closing.end(), [&](int a, int b) { return angles[a] > angles[b]; });
    std::sort(opening.begin(), opening.end(), [&](int a, int b) { return angles[a] < angles[b]; });

    std::vector<Configuration> configs(angles.size(), start.configuration);
    std::vector<bool> reached(angles.size(), true);
    FoldSweep& sweep = result.value;
    // Components move independently: each is followed by one thread, writing only its own
    // bodies' poses, and the findings are merged in component order, so the result does not
    // depend on the scheduling.
    struct Track {
        size_t reached = 0; ///< how many angles of the run it reached
        double locked_at = -1.0;
        bool branch_followed = true;
    };
    const size_t components = g.components.size();
    for (const std::vector<int>* run : {&closing, &opening}) {
        std::vector<Track> tracks(components);
        // Each thread keeps its component's poses to itself until the end: written straight
        // into the shared configurations, neighbouring bodies of two threads share cache lines.
        std::vector<std::vector<BodyPose>> poses(components);
        tbb::parallel_for(size_t(0), components, [&](size_t c) {
            ComponentTrack track(solver, int(c), start.angle, start.configuration, start.design);
            const std::vector<int>& bodies = g.components[c];
            std::vector<BodyPose>& mine = poses[c];
            mine.reserve(run->size() * bodies.size());
            size_t k = 0;
            for (; k < run->size(); ++k) {
                stop_if_cancelled(solver.options().cancel, kWork);
                if (!track.advance_to(angles[(*run)[k]]))
                    break;
                for (int b : bodies)
                    mine.push_back(track.configuration()[b]);
            }
            tracks[c] = {k, k < run->size() ? track.locked_angle() : -1.0, track.branch_followed()};
        });
        for (size_t c = 0; c < components; ++c) {
            const std::vector<int>& bodies = g.components[c];
            for (size_t k = 0; k < tracks[c].reached; ++k)
                for (size_t n = 0; n < bodies.size(); ++n)
                    configs[(*run)[k]][bodies[n]] = poses[c][k * bodies.size() + n];
        }
        for (size_t c = 0; c < components; ++c) {
            const Track& t = tracks[c];
            if (t.reached < run->size()) {
                for (size_t k = t.reached; k < run->size(); ++k)
                    reached[(*run)[k]] = false;
                const double at = t.locked_at;
                const bool closer = run == &closing;
                if (sweep.locked_at < 0.0 || (closer ? at > sweep.locked_at : at < sweep.locked_at))
                    sweep.locked_at = at;
                const std::vector<int> ids = component_patches(s, g, int(c));
                result.warn(DiagnosticCode::motion_locked,
                            std::string("the motion locks at ") + degrees(at) + " while " +
                                (closer ? "closing" : "opening") +
                                ": the patches cannot move further without bending or tearing" +
                                patch_list(s, ids),
                            about_patches(ids, at * 180.0 / M_PI));
            }
            if (!t.branch_followed)
                result.warn(DiagnosticCode::branch_not_followed,
                            "a flat fold left the design state against its fold direction" +
                                patch_list(s, component_patches(s, g, int(c))),
                            about_patches(component_patches(s, g, int(c))));
        }
    }
    sweep.complete = std::all_of(reached.begin(), reached.end(), [](bool r) { return r; });
    std::vector<size_t> posed;
    for (size_t i = 0; i < angles.size(); ++i)
        if (reached[i])
            posed.push_back(i);
    sweep.states.resize(posed.size());
    tbb::parallel_for(size_t(0), posed.size(), [&](size_t k) {
        const size_t i = posed[k];
        solver.drive_base(angles[i], configs[i]);
        sweep.states[k] = solver.state(angles[i], configs[i]);
    });
    return result;
}

// Validates the scaffold and the angles; on success fills `checked` and `graph`.
bool prepare(const Scaffold& input, const std::vector<double>& angles, Result<FoldSweep>& result,
             Result<Scaffold>& checked, Result<BodyGraph>& graph)
{
    checked = validate_scaffold(input);
    if (!checked.ok) {
        result.ok = false;
        result.diagnostics = checked.diagnostics;
        return false;
    }
    for (double a : angles)
        if (!(a >= 0.0 && a <= M_PI)) {
            std::ostringstream m;
            m << "fold angle " << a << " rad is outside 0..π (0°..180°)";
            result.fail(DiagnosticCode::angle_out_of_range, m.str(), about_parameter("angles"));
        }
    if (!result.ok)
        return false;
    graph = build_body_graph(checked.value);
    if (!graph.ok) {
        result.ok = false;
        result.diagnostics = graph.diagnostics;
        return false;
    }
    return true;
}

void append(Result<FoldSweep>& to, Result<FoldSweep>&& from)
{
    to.value = std::move(from.value);
    to.ok = to.ok && from.ok;
    to.diagnostics.insert(to.diagnostics.end(), from.diagnostics.begin(), from.diagnostics.end());
}

} // namespace

Result<FoldSweep> simulate_fold(const Scaffold& input, const std::vector<double>& angles,
                                const SimulationOptions& options)
{
    Result<FoldSweep> result;
    Result<Scaffold> checked;
    Result<BodyGraph> graph;
    if (!prepare(input, angles, result, checked, graph))
        return result;
    const FoldSolver solver(checked.value, graph.value, options);
    append(result, simulate_validated(solver, angles));
    return result;
}

Result<FoldSweep> simulate_validated(const FoldSolver& solver, const std::vector<double>& angles)
{
    Result<FoldSweep> result;
    const Scaffold& s = solver.scaffold();
    const BodyGraph& g = solver.graph();
    Configuration design = solver.design_configuration();
    solver.drive_base(s.design_angle, design);
    append(result, sweep_from(s, g, solver, {s.design_angle, design, true}, angles));

    // A flat fold without a direction matters only where the design state is a branch point.
    for (size_t c = 0; c < g.components.size(); ++c) {
        if (solver.undirected_flat_hinges(c).empty() || !solver.singular(int(c), design))
            continue;
        std::ostringstream m;
        m << "hinge " << s.hinges[solver.undirected_flat_hinges(c)[0]].id
          << " is flat at the design state, where the motion can branch, and has no fold "
             "direction; set \"fold\" to valley or mountain to choose how it pops";
        const Hinge& h = s.hinges[solver.undirected_flat_hinges(c)[0]];
        result.warn(DiagnosticCode::undirected_flat_fold, m.str(),
                    about_patches({h.patch_a, h.patch_b}));
    }
    return result;
}

Result<FoldSweep> continue_fold(const Scaffold& input, const FoldState& from,
                                const std::vector<double>& angles, const SimulationOptions& options)
{
    Result<FoldSweep> result;
    Result<Scaffold> checked;
    Result<BodyGraph> graph;
    if (!prepare(input, angles, result, checked, graph))
        return result;
    const Scaffold& s = checked.value;
    if (from.poses.size() != s.patches.size() || !(from.angle >= 0.0 && from.angle <= M_PI)) {
        result.fail(DiagnosticCode::bad_start_state,
                    "the start state has " + std::to_string(from.poses.size()) + " poses for " +
                        std::to_string(s.patches.size()) + " patches, or an angle outside 0..π",
                    about_parameter("from"));
        return result;
    }
    const FoldSolver solver(s, graph.value, options);
    // The design state itself is a possible branch point: start there the hinted way.
    if (std::abs(from.angle - s.design_angle) < 1e-12)
        return simulate_fold(input, angles, options);
    Configuration start = solver.configuration(from);
    solver.drive_base(from.angle, start);
    append(result, sweep_from(s, graph.value, solver, {from.angle, start, false}, angles));
    return result;
}

} // namespace popup
