#include "popup/simulate_fold.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

#include "body_graph.hpp"
#include "fold_solver.hpp"

namespace popup {

namespace {

std::string degrees(double radians)
{
    std::ostringstream s;
    s.precision(4);
    s << radians * 180.0 / M_PI << "°";
    return s.str();
}

std::string patch_list(const Scaffold& s, const BodyGraph& g, int component)
{
    std::ostringstream out;
    bool first = true;
    for (size_t i = 0; i < s.patches.size(); ++i) {
        const int b = g.body_of_patch[i];
        if (g.is_base(b) || g.component_of_body[b] != component)
            continue;
        out << (first ? "" : ", ") << "patch " << s.patches[i].id;
        if (!s.patches[i].name.empty())
            out << " (" << s.patches[i].name << ")";
        first = false;
    }
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

Result<FoldSweep> simulate_fold(const Scaffold& input, const std::vector<double>& angles,
                                const SimulationOptions& options)
{
    Result<FoldSweep> result;
    Result<Scaffold> checked = validate_scaffold(input);
    if (!checked.ok) {
        result.ok = false;
        result.diagnostics = checked.diagnostics;
        return result;
    }
    const Scaffold& s = checked.value;
    for (double a : angles)
        if (!(a >= 0.0 && a <= M_PI)) {
            std::ostringstream m;
            m << "fold angle " << a << " rad is outside 0..π (0°..180°)";
            result.fail("angle_out_of_range", m.str(), "angles");
        }
    if (!result.ok)
        return result;
    Result<BodyGraph> graph = build_body_graph(s);
    if (!graph.ok) {
        result.ok = false;
        result.diagnostics = graph.diagnostics;
        return result;
    }
    const BodyGraph& g = graph.value;
    const FoldSolver solver(s, g, options);

    // Closing and opening runs leave the design state in opposite directions.
    std::vector<int> order(angles.size());
    std::iota(order.begin(), order.end(), 0);
    std::vector<int> closing, opening;
    for (int i : order)
        (angles[i] <= s.design_angle ? closing : opening).push_back(i);
    std::sort(closing.begin(), closing.end(), [&](int a, int b) { return angles[a] > angles[b]; });
    std::sort(opening.begin(), opening.end(), [&](int a, int b) { return angles[a] < angles[b]; });

    std::vector<Configuration> configs(angles.size(), solver.design_configuration());
    std::vector<bool> reached(angles.size(), true);
    FoldSweep& sweep = result.value;
    for (const std::vector<int>* run : {&closing, &opening}) {
        for (size_t c = 0; c < g.components.size(); ++c) {
            ComponentTrack track(solver, int(c), s.design_angle);
            size_t k = 0;
            for (; k < run->size(); ++k) {
                const int i = (*run)[k];
                if (!track.advance_to(angles[i]))
                    break;
                for (int b : g.components[c])
                    configs[i][b] = track.configuration()[b];
            }
            if (k < run->size()) {
                for (; k < run->size(); ++k)
                    reached[(*run)[k]] = false;
                const double at = track.locked_angle();
                const bool closer = run == &closing;
                if (sweep.locked_at < 0.0 || (closer ? at > sweep.locked_at : at < sweep.locked_at))
                    sweep.locked_at = at;
                result.warn("motion_locked",
                            std::string("the motion locks at ") + degrees(at) + " while " +
                                (closer ? "closing" : "opening") +
                                ": the patches cannot move further without bending or tearing",
                            patch_list(s, g, int(c)));
            }
            if (!track.branch_followed())
                result.warn("branch_not_followed",
                            "a flat fold left the design state against its fold direction",
                            patch_list(s, g, int(c)));
        }
    }
    // A flat fold without a direction matters only where the design state is a branch point.
    const Configuration design = solver.design_configuration();
    for (size_t c = 0; c < g.components.size(); ++c) {
        if (solver.undirected_flat_hinges(c).empty() || !solver.singular(int(c), design))
            continue;
        std::ostringstream m;
        m << "hinge " << s.hinges[solver.undirected_flat_hinges(c)[0]].id
          << " is flat at the design state, where the motion can branch, and has no fold "
             "direction; set \"fold\" to valley or mountain to choose how it pops";
        result.warn("undirected_flat_fold", m.str(), patch_list(s, g, int(c)));
    }
    sweep.complete = std::all_of(reached.begin(), reached.end(), [](bool r) { return r; });
    for (size_t i = 0; i < angles.size(); ++i) {
        if (!reached[i])
            continue;
        solver.drive_base(angles[i], configs[i]);
        sweep.states.push_back(solver.state(angles[i], configs[i]));
    }
    return result;
}

} // namespace popup
