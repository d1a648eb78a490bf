// The only translation unit that includes OCCT headers: CGAL and OCCT clash (OCCT's Handle
// macro), so no CGAL here, and nothing OCCT leaks into popup's public headers.
#include "popup/io/brep_export.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <set>
#include <sstream>
#include <stdexcept>

// OCCT 7.6 headers derive from the deprecated std::iterator; that is theirs to fix.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepCheck.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepCheck_ListOfStatus.hxx>
#include <BRepCheck_Result.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <Precision.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Dir.hxx>
#include <gp_Pln.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>
#pragma GCC diagnostic pop

namespace popup {
namespace {

std::string patch_label(const Patch& patch)
{
    return "patch " + std::to_string(patch.id) + " (\"" + patch.name + "\")";
}

/// "OCCT <type>: <message>" of an OCCT exception, which is not a std::exception in 7.6.
std::string occt_message(const Standard_Failure& e)
{
    const char* message = e.GetMessageString();
    return std::string("OCCT ") + e.DynamicType()->Name() + ": " +
           (message && *message ? message : "(no message)");
}

/// Drops a repeated closing vertex and consecutive duplicates: OCCT wants distinct vertices.
Loop3 cleaned(const Loop3& loop, double tolerance)
{
    Loop3 out;
    for (const Vec3& p : loop)
        if (out.empty() || (p - out.back()).norm() > tolerance)
            out.push_back(p);
    while (out.size() > 1 && (out.front() - out.back()).norm() <= tolerance)
        out.pop_back();
    return out;
}

/// Newell's normal (not normalised): twice the vector area, its direction follows the winding.
Vec3 newell(const Loop3& loop)
{
    Vec3 n = Vec3::Zero();
    for (std::size_t i = 0; i < loop.size(); ++i) {
        const Vec3& a = loop[i];
        const Vec3& b = loop[(i + 1) % loop.size()];
        n += a.cross(b);
    }
    return n;
}

void check_finite(const Patch& patch, const Loop3& loop, const char* what)
{
    for (const Vec3& p : loop)
        if (!p.allFinite())
            throw std::invalid_argument(patch_label(patch) + ": " + what +
                                        " has a non-finite coordinate");
}

void check_size(const Patch& patch, const Loop3& loop, const char* what)
{
    if (loop.size() < 3)
        throw std::invalid_argument(patch_label(patch) + ": " + what + " has " +
                                    std::to_string(loop.size()) +
                                    " distinct vertices, needs at least 3");
}

Loop3 posed(const Loop3& loop, const Pose& pose)
{
    Loop3 out;
    out.reserve(loop.size());
    for (const Vec3& p : loop)
        out.push_back(pose.apply(p));
    return out;
}

void check_pose(const Patch& patch, const Pose& pose)
{
    if (!pose.rotation.allFinite() || !pose.translation.allFinite())
        throw std::invalid_argument(patch_label(patch) + ": pose has a non-finite entry");
}

/// Closed polygon wire of `loop` projected onto the plane (point `o`, unit normal `n`), so the
/// face is exactly planar even when the simulator left the vertices a hair off the plane.
TopoDS_Wire make_wire(const Loop3& loop, const Vec3& o, const Vec3& n, bool reversed)
{
    BRepBuilderAPI_MakePolygon polygon;
    const std::size_t count = loop.size();
    for (std::size_t k = 0; k < count; ++k) {
        const Vec3& p = loop[reversed ? count - 1 - k : k];
        const Vec3 q = p - n * n.dot(p - o);
        polygon.Add(gp_Pnt(q.x(), q.y(), q.z()));
    }
    polygon.Close();
    if (!polygon.IsDone())
        throw std::runtime_error("could not build a closed polygon");
    return polygon.Wire();
}

/// Names of the BRepCheck statuses found anywhere in `shape`, for an error a person can act on.
std::string check_failures(const BRepCheck_Analyzer& analyzer, const TopoDS_Shape& shape)
{
    std::set<std::string> names;
    const TopAbs_ShapeEnum types[] = {TopAbs_VERTEX, TopAbs_EDGE,  TopAbs_WIRE,
                                      TopAbs_FACE,   TopAbs_SHELL, TopAbs_SOLID};
    auto collect = [&](const BRepCheck_ListOfStatus& list) {
        for (BRepCheck_ListOfStatus::Iterator it(list); it.More(); it.Next()) {
            if (it.Value() == BRepCheck_NoError)
                continue;
            std::ostringstream name;
            BRepCheck::Print(it.Value(), name);
            std::string text = name.str();
            while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back())))
                text.pop_back();
            names.insert(text);
        }
    };
    for (TopAbs_ShapeEnum type : types) {
        for (TopExp_Explorer ex(shape, type); ex.More(); ex.Next()) {
            const Handle(BRepCheck_Result)& result = analyzer.Result(ex.Current());
            if (result.IsNull())
                continue;
            collect(result->Status());
            for (result->InitContextIterator(); result->MoreShapeInContext();
                 result->NextShapeInContext())
                collect(result->StatusOnShape());
        }
    }
    std::string out;
    for (const std::string& name : names)
        out += (out.empty() ? "" : ", ") + name;
    return out.empty() ? "invalid shape" : out;
}

/// The face (or solid) of one patch at `pose`.
TopoDS_Shape patch_shape(const Patch& patch, const Pose& pose, double thickness)
{
    // Finiteness first: cleaning compares distances, and NaN compares false.
    check_finite(patch, patch.outer, "outer loop");
    for (const Loop3& hole : patch.holes)
        check_finite(patch, hole, "hole");
    // Scale-aware tolerance: a vertex within 1e-9 of the patch size is the same vertex.
    double extent = 0.0;
    for (const Vec3& p : patch.outer)
        extent = std::max(extent, (p - patch.outer.front()).norm());
    const double tolerance = std::max(Precision::Confusion(), 1e-9 * extent);
    const Loop3 outer = cleaned(posed(patch.outer, pose), tolerance);
    check_size(patch, outer, "outer loop");
    std::vector<Loop3> holes;
    for (const Loop3& hole : patch.holes) {
        holes.push_back(cleaned(posed(hole, pose), tolerance));
        check_size(patch, holes.back(), "hole");
    }

    // The normal is Newell's of the posed outer loop: the same as pose.rotation * patch.normal
    // once the frame is derived, and still right for a scaffold that never went through
    // validate_scaffold.
    const Vec3 area_vector = newell(outer);
    if (area_vector.norm() <= tolerance * std::max(extent, 1.0))
        throw std::invalid_argument(patch_label(patch) + ": outer loop encloses no area");
    const Vec3 n = area_vector.normalized();
    Vec3 o = Vec3::Zero();
    for (const Vec3& p : outer)
        o += p;
    o /= static_cast<double>(outer.size());
    // Thickened paper is centred on the patch plane: hinges then lie on the paper's mid-surface,
    // which is where the simulator puts them, and both sides of a fold get the same offset.
    if (thickness > 0.0)
        o -= 0.5 * thickness * n;

    const gp_Pln plane(gp_Pnt(o.x(), o.y(), o.z()), gp_Dir(n.x(), n.y(), n.z()));
    // Outer loop counter-clockwise about n by construction of n; holes must run the other way,
    // whatever winding the caller stored.
    BRepBuilderAPI_MakeFace maker(plane, make_wire(outer, o, n, false), Standard_True);
    if (!maker.IsDone())
        throw std::runtime_error("face construction failed (error " +
                                 std::to_string(static_cast<int>(maker.Error())) + ")");
    for (const Loop3& hole : holes) {
        const bool counter_clockwise = newell(hole).dot(n) > 0.0;
        maker.Add(make_wire(hole, o, n, counter_clockwise));
    }
    if (!maker.IsDone())
        throw std::runtime_error("adding a hole failed (error " +
                                 std::to_string(static_cast<int>(maker.Error())) + ")");
    TopoDS_Shape shape = maker.Face();

    if (thickness > 0.0) {
        const Vec3 d = thickness * n;
        BRepPrimAPI_MakePrism prism(shape, gp_Vec(d.x(), d.y(), d.z()), Standard_True);
        if (!prism.IsDone())
            throw std::runtime_error("thickening failed");
        shape = prism.Shape();
    }

    BRepCheck_Analyzer analyzer(shape);
    if (!analyzer.IsValid())
        throw std::runtime_error("BRepCheck_Analyzer: " + check_failures(analyzer, shape));
    return shape;
}

} // namespace

std::string patches_to_brep(const Scaffold& scaffold, const FoldState& state,
                            const BrepOptions& options)
{
    if (state.poses.size() != scaffold.patches.size())
        throw std::invalid_argument("patches_to_brep: fold state has " +
                                    std::to_string(state.poses.size()) + " poses for " +
                                    std::to_string(scaffold.patches.size()) +
                                    " patches of scaffold \"" + scaffold.name + "\"");
    // Paper, not a block: a thickness beyond 5% of the model (as for design files) would make
    // OCCT's prisms fail with a bare "gp_Dir() - input vector has zero norm".
    const double largest = 0.05 * std::max(scaffold.size(), 1.0);
    if (!std::isfinite(options.thickness) || options.thickness < 0.0 ||
        options.thickness > largest) {
        std::ostringstream m;
        m << "patches_to_brep: thickness = " << options.thickness << " mm, must be 0 to " << largest
          << " mm (5% of the model size)";
        throw std::invalid_argument(m.str());
    }

    BRep_Builder builder;
    TopoDS_Compound compound;
    builder.MakeCompound(compound);
    for (std::size_t i = 0; i < scaffold.patches.size(); ++i) {
        const Patch& patch = scaffold.patches[i];
        check_pose(patch, state.poses[i]);
        // invalid_argument (a logic_error) passes through untouched; OCCT's own exception family is
        // not a std::exception in 7.6, so it is translated here, where the patch is still known.
        try {
            builder.Add(compound, patch_shape(patch, state.poses[i], options.thickness));
        } catch (const std::runtime_error& e) {
            throw std::runtime_error(patch_label(patch) + ": " + e.what());
        } catch (const Standard_Failure& e) {
            throw std::runtime_error(patch_label(patch) + ": " + occt_message(e));
        }
    }

    std::ostringstream out;
    try {
        BRepTools::Write(compound, out);
    } catch (const Standard_Failure& e) {
        throw std::runtime_error("patches_to_brep: writing BREP failed: " + occt_message(e));
    }
    return out.str();
}

std::string design_to_brep(const Scaffold& scaffold, const BrepOptions& options)
{
    FoldState state;
    state.angle = scaffold.design_angle;
    state.poses.assign(scaffold.patches.size(), Pose{});
    return patches_to_brep(scaffold, state, options);
}

} // namespace popup
