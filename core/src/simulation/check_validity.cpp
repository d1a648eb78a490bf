#include "popup/simulation/check_validity.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include <tbb/parallel_for.h>

#include "../geometry/indexed_loops.hpp"
#include "../geometry/polygon_2d.hpp"
#include "../model/millimetres.hpp"
#include "body_graph.hpp"
#include "crossing_test.hpp"
#include "fold_solver.hpp"
#include "free_motion.hpp"
#include "simulate_validated.hpp"

namespace popup {

namespace {

// Checkpoints sit in inner loops: a literal became a std::string per call (116 000 allocations
// in one check of a 100-patch card).
const std::string kWork = "the validity check";

std::string deg(double radians)
{
    std::ostringstream s;
    s.setf(std::ios::fixed);
    s.precision(2);
    s << radians * 180.0 / M_PI << "°";
    return s.str();
}

/// Everything the checks share: the validated scaffold, its bodies, the solver and the meshes.
struct Checker {
    const Scaffold& s;
    const BodyGraph& graph;
    const FoldSolver& solver;
    const std::vector<PatchMesh>& meshes;
    double tolerance;
    double clearance;

    // State at `theta` between two solved states, by interpolation and correction.
    bool solve_between(const FoldState& a, const FoldState& b, double theta, FoldState& out) const
    {
        const double t = (theta - a.angle) / (b.angle - a.angle);
        Configuration qa = solver.configuration(a);
        const Configuration qb = solver.configuration(b);
        for (int body = 0; body < graph.body_count; ++body) {
            const Mat3 turn = qb[body].rotation * qa[body].rotation.transpose();
            qa[body].rotation = rotation_exp(t * rotation_log(turn)) * qa[body].rotation;
            qa[body].position += t * (qb[body].position - qa[body].position);
        }
        solver.drive_base(theta, qa);
        for (size_t c = 0; c < graph.components.size(); ++c)
            if (!solver.correct(int(c), qa, {}, 60))
                return false;
        out = solver.state(theta, qa);
        return true;
    }

    double depth(const PosedPatches& posed, int i, int j) const
    {
        return crossing_depth(meshes, posed, s, i, j, tolerance, clearance);
    }

    // Angle where the pair starts crossing, between a state without and one with a crossing.
    double onset(FoldState free, FoldState crossing, int i, int j, int levels) const
    {
        for (int level = 0; level < levels; ++level) {
            FoldState mid;
            if (!solve_between(free, crossing, 0.5 * (free.angle + crossing.angle), mid))
                break;
            (depth(pose_patches(meshes, mid, {i, j}), i, j) > 0.0 ? crossing : free) = mid;
        }
        return crossing.angle;
    }

    // Signed distance of vertex k of patch i from patch j's plane at `st`.
    double side_at(const FoldState& st, int i, int j, size_t k) const
    {
        const Pose& pj = st.poses[j];
        const Vec3 normal = pj.rotation * s.patches[j].normal;
        const Vec3 origin = pj.apply(s.patches[j].origin);
        return (st.poses[i].apply(meshes[i].vertices[k]) - origin).dot(normal);
    }

    // A vertex of patch i that changes side of patch j's plane between two states, at a point
    // inside patch j: the patch passed through. Returns how far the vertex went, or 0.
    double passes_through(const PosedPatches& pa, const PosedPatches& pb, int i, int j,
                          int levels) const
    {
        const FoldState& a = *pa.state;
        const FoldState& b = *pb.state;
        const Vec3 na = a.poses[j].rotation * s.patches[j].normal;
        const Vec3 nb = b.poses[j].rotation * s.patches[j].normal;
        const Vec3 oa = a.poses[j].apply(s.patches[j].origin);
        const Vec3 ob = b.poses[j].apply(s.patches[j].origin);
        for (size_t k = 0; k < meshes[i].vertices.size(); ++k) {
            const double da = (pa.vertices[i][k] - oa).dot(na);
            const double db = (pb.vertices[i][k] - ob).dot(nb);
            if (!((da > tolerance && db < -tolerance) || (da < -tolerance && db > tolerance)))
                continue;
            FoldState lo = a, hi = b;
            double dlo = da, dhi = db;
            for (int level = 0; level < levels; ++level) {
                FoldState mid;
                if (!solve_between(lo, hi, 0.5 * (lo.angle + hi.angle), mid))
                    break;
                const double dm = side_at(mid, i, j, k);
                if ((dm > 0.0) == (dlo > 0.0)) {
                    lo = mid;
                    dlo = dm;
                } else {
                    hi = mid;
                    dhi = dm;
                }
            }
            // Where the vertex meets the plane, in patch j's own frame.
            const Vec3 x_lo = lo.poses[i].apply(meshes[i].vertices[k]);
            const Vec3 x_hi = hi.poses[i].apply(meshes[i].vertices[k]);
            const Vec3 hit = x_lo + (x_hi - x_lo) * (dlo / (dlo - dhi));
            const Pose& pj = lo.poses[j];
            const Vec2 q = s.patches[j].to_local(pj.rotation.transpose() * (hit - pj.translation));
            // On the paper: inside the outline and out of every hole (a window it goes through).
            const std::vector<Loop2> holes = s.patches[j].holes_local();
            const bool in_window = std::any_of(holes.begin(), holes.end(), [&](const Loop2& h) {
                return point_in_polygon_or_near(h, q, tolerance);
            });
            if (!in_window && point_in_polygon_or_near(s.patches[j].outer_local(), q, -tolerance))
                return std::max(std::abs(da), std::abs(db));
        }
        return 0.0;
    }
};

struct PairFinding {
    double angle = 0.0;
    double depth = 0.0;
};

} // namespace

std::vector<Crossing> find_crossings(const Scaffold& input, const FoldState& state,
                                     double tolerance)
{
    Result<Scaffold> checked = validate_scaffold(input);
    if (!checked.ok)
        throw std::invalid_argument("find_crossings: invalid scaffold: " +
                                    checked.diagnostics.front().message);
    const Scaffold& s = checked.value;
    if (state.poses.size() != s.patches.size())
        throw std::invalid_argument("find_crossings: the state has " +
                                    std::to_string(state.poses.size()) + " poses for " +
                                    std::to_string(s.patches.size()) + " patches");
    Result<BodyGraph> graph = build_body_graph(s);
    if (!graph.ok)
        throw std::invalid_argument("find_crossings: " + graph.diagnostics.front().message);
    const std::vector<PatchMesh> meshes = mesh_patches(s);
    const PosedPatches posed = pose_patches(meshes, state);
    std::vector<Crossing> out;
    for (const auto& [i, j] : candidate_pairs(posed, graph.value.body_of_patch, tolerance)) {
        const double d = crossing_depth(meshes, posed, s, i, j, tolerance, 0.0);
        if (d > 0.0)
            out.push_back({s.patches[i].id, s.patches[j].id, state.angle, d});
    }
    return out;
}

namespace {

void add_error(ValidityReport& report, DiagnosticCode code, std::string message,
               DiagnosticSubject about = {})
{
    report.diagnostics.push_back(Diagnostic::error(code, std::move(message), std::move(about)));
}

// False, with the reason in `report`, when an option is out of its range.
bool options_in_range(const ValidityOptions& options, double size, ValidityReport& report)
{
    if (options.samples < 2 || options.samples > 100000) {
        add_error(report, DiagnosticCode::bad_option,
                  "samples = " + std::to_string(options.samples) + ", must be 2 to 100000",
                  about_parameter("samples"));
        return false;
    }
    // A gap wider than a twentieth of the card is no clearance any more: patches stand further
    // apart than that only far from each other, and the proximity test loses its meaning.
    const double largest_clearance = 0.05 * size;
    if (!(options.clearance >= 0.0 && options.clearance <= largest_clearance)) {
        std::ostringstream m;
        m << "clearance = " << options.clearance << " mm, must be 0 to " << largest_clearance
          << " mm (5% of the model size)";
        add_error(report, DiagnosticCode::bad_option, m.str(), about_parameter("clearance"));
        return false;
    }
    if (options.refine_depth < 0 || options.refine_depth > 30) {
        add_error(report, DiagnosticCode::bad_option,
                  "refine_depth = " + std::to_string(options.refine_depth) + ", must be 0 to 30",
                  about_parameter("refine_depth"));
        return false;
    }
    return true;
}

// Sampled angles from open to closed, with the design state among them.
// π·k/(n-1) need not round to π at k = n-1: a sample a hair below the flat design state
// would be judged as an open state (stability, crossings) though it is the design state.
// Samples within rounding of the design angle are the design angle, exactly.
std::vector<double> sample_angles(const Scaffold& s, int samples)
{
    std::vector<double> angles;
    for (int k = samples - 1; k >= 0; --k) {
        const double a = M_PI * k / (samples - 1);
        angles.push_back(std::abs(a - s.design_angle) < 1e-12 ? s.design_angle : a);
    }
    if (std::none_of(angles.begin(), angles.end(), [&](double a) { return a == s.design_angle; })) {
        angles.push_back(s.design_angle);
        std::sort(angles.rbegin(), angles.rend());
    }
    return angles;
}

// Foldable: the motion exists from 180° to 0°, stays rigid, and ends flat. Returns the closed
// state, if the sweep reached it.
const FoldState* judge_foldable(const Scaffold& s, const Result<FoldSweep>& sim,
                                double flat_tolerance, ValidityReport& report)
{
    const FoldSweep& sweep = sim.value;
    const double size = s.size();
    for (const FoldState& st : sweep.states) {
        report.max_hinge_residual = std::max(report.max_hinge_residual, st.hinge_residual);
        report.max_edge_strain = std::max(report.max_edge_strain, st.edge_strain);
    }
    const FoldState* closed = nullptr;
    for (const FoldState& st : sweep.states)
        if (st.angle == 0.0)
            closed = &st;
    if (closed) {
        int worst = -1;
        for (size_t i = 0; i < s.patches.size(); ++i)
            for (const Vec3& x : posed_outline(s.patches[i], closed->poses[i]))
                if (std::abs(x.x()) > report.flatness_at_zero) {
                    report.flatness_at_zero = std::abs(x.x());
                    worst = int(i);
                }
        if (report.flatness_at_zero > flat_tolerance)
            add_error(report, DiagnosticCode::not_flat_when_closed,
                      patch_subject(s.patches[worst]) + " stands " +
                          millimetres(report.flatness_at_zero) +
                          " off the page plane when the card is closed (allowed " +
                          millimetres(flat_tolerance) + ")",
                      about_patches({s.patches[worst].id}, 0.0));
    }
    const bool branch_ok =
        std::none_of(sim.diagnostics.begin(), sim.diagnostics.end(), [](const Diagnostic& d) {
            return d.code == DiagnosticCode::branch_not_followed;
        });
    report.foldable = sim.ok && sweep.complete && closed &&
                      report.flatness_at_zero <= flat_tolerance &&
                      report.max_hinge_residual <= 1e-9 * size && branch_ok;
    return closed;
}

// Stable: no free motion with the base held still, at every sampled angle strictly between.
// Components are independent and each owns its solver buffers: one thread per component,
// every sample in turn; the verdicts are merged in sample order.
void judge_stable(const Scaffold& s, const BodyGraph& graph, const FoldSolver& solver,
                  const FoldSweep& sweep, const CancelFlag* cancel, ValidityReport& report)
{
    std::vector<size_t> between;
    for (size_t k = 0; k < sweep.states.size(); ++k)
        if (sweep.states[k].angle > 0.0 && sweep.states[k].angle < M_PI)
            between.push_back(k);
    std::vector<Configuration> configurations(between.size());
    tbb::parallel_for(size_t(0), between.size(), [&](size_t k) {
        configurations[k] = solver.configuration(sweep.states[between[k]]);
    });
    const size_t components = graph.components.size();
    std::vector<std::vector<ComponentMotion>> motions(components);
    tbb::parallel_for(size_t(0), components, [&](size_t c) {
        motions[c].resize(between.size());
        for (size_t k = 0; k < between.size(); ++k) {
            stop_if_cancelled(cancel, kWork);
            motions[c][k] = component_free_motion(solver, int(c), configurations[k]);
        }
    });
    int unstable_samples = 0;
    for (size_t k = 0; k < between.size(); ++k) {
        int dimension = 0;
        std::vector<int> bodies;
        for (size_t c = 0; c < components; ++c) {
            dimension += motions[c][k].dimension;
            bodies.insert(bodies.end(), motions[c][k].moving_bodies.begin(),
                          motions[c][k].moving_bodies.end());
        }
        if (dimension == 0)
            continue;
        if (unstable_samples++ == 0) {
            std::sort(bodies.begin(), bodies.end());
            const std::vector<int> moving = patches_of_bodies(s, graph, bodies);
            const FoldState& st = sweep.states[between[k]];
            std::ostringstream names;
            for (size_t i = 0; i < moving.size(); ++i)
                names << (i ? ", " : "") << patch_subject(*s.find_patch(moving[i]));
            add_error(report, DiagnosticCode::unstable,
                      std::to_string(dimension) + " free motion(s) besides the fold angle at " +
                          deg(st.angle) + ": " + names.str() +
                          " can move while the base is held still",
                      about_patches(moving, st.angle * 180.0 / M_PI));
        }
    }
    report.stable = unstable_samples == 0 && !sweep.states.empty();
}

// Intersection-free: no transversal cut at a sample and no pass-through between samples.
void judge_intersection_free(const Checker& checker, const FoldSweep& sweep,
                             const ValidityOptions& options, ValidityReport& report)
{
    const Scaffold& s = checker.s;
    const BodyGraph& graph = checker.graph;
    const std::vector<PatchMesh>& meshes = checker.meshes;
    // Each sample (and the gap before it) is judged on its own, on all cores; only a pair's
    // onset depends on whether it crossed at the sample before, so that is done in order.
    struct PairAtSample {
        int i, j;
        double depth;   ///< > 0: crossing at the sample
        double through; ///< > 0: passed through between the previous sample and this one
    };
    const double margin = checker.tolerance + options.clearance;
    std::vector<std::vector<PairAtSample>> samples(sweep.states.size());
    tbb::parallel_for(size_t(0), sweep.states.size(), [&](size_t k) {
        stop_if_cancelled(options.cancel, kWork);
        // Each patch posed once at this sample and once at the one before, for every pair, into
        // buffers each thread keeps (nothing in this body waits on other tasks).
        thread_local PosedPatches here, before;
        pose_patches(meshes, sweep.states[k], here);
        if (k)
            pose_patches(meshes, sweep.states[k - 1], before);
        for (const auto& [i, j] : candidate_pairs(here, graph.body_of_patch, margin)) {
            stop_if_cancelled(options.cancel, kWork); // a pair may be refined
            PairAtSample p{i, j, checker.depth(here, i, j), 0.0};
            if (p.depth <= 0.0 && k)
                p.through =
                    std::max(checker.passes_through(before, here, i, j, options.refine_depth),
                             checker.passes_through(before, here, j, i, options.refine_depth));
            samples[k].push_back(p);
        }
    });
    std::map<std::pair<int, int>, PairFinding> findings;
    std::map<std::pair<int, int>, bool> was_crossing;
    for (size_t k = 0; k < sweep.states.size(); ++k) {
        const FoldState& st = sweep.states[k];
        const FoldState* previous = k ? &sweep.states[k - 1] : nullptr;
        for (const PairAtSample& p : samples[k]) {
            const std::pair<int, int> key{p.i, p.j};
            double depth = p.depth;
            double at = st.angle;
            if (depth > 0.0 && previous && !was_crossing[key]) {
                stop_if_cancelled(options.cancel, kWork);
                at = checker.onset(*previous, st, p.i, p.j, options.refine_depth);
            } else if (depth <= 0.0 && p.through > 0.0) {
                depth = p.through;
                at = 0.5 * (previous->angle + st.angle);
            }
            was_crossing[key] = depth > 0.0;
            if (depth <= 0.0)
                continue;
            auto [it, fresh] = findings.try_emplace(key, PairFinding{at, depth});
            if (!fresh)
                it->second.depth = std::max(it->second.depth, depth);
        }
    }
    for (const auto& [key, f] : findings) {
        const Patch& a = s.patches[key.first];
        const Patch& b = s.patches[key.second];
        report.crossings.push_back({a.id, b.id, f.angle, f.depth});
        add_error(report, DiagnosticCode::intersection,
                  patch_subject(a) + " passes through " + patch_subject(b) + " from " +
                      deg(f.angle) + " (deepest " + millimetres(f.depth) + ")",
                  about_patches({a.id, b.id}, f.angle * 180.0 / M_PI));
    }
    report.intersection_free = findings.empty() && !sweep.states.empty();
}

// Enclosed: when closed, every patch lies inside the base patches' outline.
void judge_enclosed(const Scaffold& s, const FoldState* closed, double flat_tolerance,
                    ValidityReport& report)
{
    if (!closed) {
        add_error(report, DiagnosticCode::enclosure_unknown,
                  "the card never closes, so enclosure cannot be judged");
        return;
    }
    std::vector<Loop2> base;
    for (int id : {s.ground, s.backdrop}) {
        const int i = s.patch_index(id);
        Loop2 loop;
        for (const Vec3& x : posed_outline(s.patches[i], closed->poses[i]))
            loop.push_back({x.y(), x.z()});
        base.push_back(loop);
    }
    // Indexed: outlines from models have tens of thousands of vertices.
    const IndexedLoops base_index[2] = {IndexedLoops({base[0]}), IndexedLoops({base[1]})};
    report.enclosed = true;
    for (size_t i = 0; i < s.patches.size(); ++i) {
        double worst = 0.0;
        Vec2 where = Vec2::Zero();
        for (const Vec3& x : posed_outline(s.patches[i], closed->poses[i])) {
            const Vec2 q(x.y(), x.z());
            if (base_index[0].contains(q) || base_index[1].contains(q))
                continue;
            const double out = std::min(base_index[0].distance_to_boundary(q),
                                        base_index[1].distance_to_boundary(q));
            if (out > worst) {
                worst = out;
                where = q;
            }
        }
        if (worst > flat_tolerance) {
            report.enclosed = false;
            std::ostringstream m;
            m << patch_subject(s.patches[i]) << " sticks out of the closed card by "
              << millimetres(worst) << " at y = " << where.x() << " mm, z = " << where.y() << " mm";
            add_error(report, DiagnosticCode::not_enclosed, m.str(),
                      about_patches({s.patches[i].id}, 0.0));
        }
    }
}

} // namespace

ValidityReport check_validity(const Scaffold& input, const ValidityOptions& options)
{
    ValidityReport report;
    Result<Scaffold> checked = validate_scaffold(input);
    if (!checked.ok) {
        report.diagnostics = checked.diagnostics;
        return report;
    }
    const Scaffold& s = checked.value;
    const double size = s.size();
    report.model_size = size;
    if (!options_in_range(options, size, report))
        return report;
    Result<BodyGraph> graph = build_body_graph(s);
    if (!graph.ok) {
        report.diagnostics = graph.diagnostics;
        return report;
    }
    SimulationOptions simulation;
    simulation.cancel = options.cancel;
    simulation.dense_linear_algebra = options.dense_linear_algebra;
    // One solver for the sweep and the checks after it; the scaffold is validated already.
    const FoldSolver solver(s, graph.value, simulation);
    const Result<FoldSweep> sim = simulate_validated(solver, sample_angles(s, options.samples));
    for (const Diagnostic& d : sim.diagnostics)
        report.diagnostics.push_back(d);
    const FoldSweep& sweep = sim.value;
    report.locked_at = sweep.locked_at;

    const double flat_tolerance = 1e-6 * size;
    const FoldState* closed = judge_foldable(s, sim, flat_tolerance, report);
    if (!sim.ok)
        return report;
    judge_stable(s, graph.value, solver, sweep, options.cancel, report);
    const std::vector<PatchMesh> meshes = mesh_patches(s);
    const Checker checker{s, graph.value, solver, meshes, flat_tolerance, options.clearance};
    judge_intersection_free(checker, sweep, options, report);
    judge_enclosed(s, closed, flat_tolerance, report);
    return report;
}

} // namespace popup
