#include "projected_faces.hpp"

#include <algorithm>
#include <cmath>
#include <future>
#include <map>
#include <tuple>
#include <utility>

#include "../geometry/clipper_paths.hpp"

namespace popup {

namespace {

// Sutherland–Hodgman against one plane: keeps the part where sign * (depth - limit) >= 0.
std::vector<Vec3> cut(const std::vector<Vec3>& polygon, const Vec3& origin, const Vec3& normal,
                      double limit, double sign)
{
    std::vector<Vec3> out;
    const size_t n = polygon.size();
    for (size_t i = 0; i < n; ++i) {
        const Vec3& a = polygon[i];
        const Vec3& b = polygon[(i + 1) % n];
        const double da = sign * ((a - origin).dot(normal) - limit);
        const double db = sign * ((b - origin).dot(normal) - limit);
        if (da >= 0)
            out.push_back(a);
        if ((da >= 0) != (db >= 0)) {
            // From the lexicographically smaller end, so that the two triangles sharing this
            // edge get the very same point and their boundaries cancel (unite_faces).
            const bool a_first =
                std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
            const Vec3& lo = a_first ? a : b;
            const Vec3& hi = a_first ? b : a;
            const double dl = a_first ? da : db, dh = a_first ? db : da;
            out.push_back(lo + (dl / (dl - dh)) * (hi - lo));
        }
    }
    return out;
}

double signed_area(const Loop2& loop)
{
    double twice = 0.0;
    for (size_t i = 0, n = loop.size(); i < n; ++i)
        twice += loop[i].x() * loop[(i + 1) % n].y() - loop[(i + 1) % n].x() * loop[i].y();
    return 0.5 * twice;
}

struct Piece {
    Loop2 outer;
    std::vector<Loop2> holes;
    double area = 0.0;
};

void collect(const ClipperLib::PolyNode& node, std::vector<Piece>& pieces)
{
    for (const ClipperLib::PolyNode* outer : node.Childs) {
        Piece piece{to_loop(outer->Contour), {}, std::abs(path_area(outer->Contour))};
        for (const ClipperLib::PolyNode* hole : outer->Childs) {
            piece.holes.push_back(to_loop(hole->Contour));
            piece.area -= std::abs(path_area(hole->Contour));
            collect(*hole, pieces);
        }
        pieces.push_back(std::move(piece));
    }
}

} // namespace

ProfileFrame posed(const ProfileFrame& frame, const std::optional<Pose>& pose)
{
    if (!pose)
        return frame;
    ProfileFrame f = frame;
    f.origin = pose->apply(frame.origin);
    f.u = pose->rotation * frame.u;
    f.v = pose->rotation * frame.v;
    f.normal = pose->rotation * frame.normal;
    return f;
}

std::vector<ProjectedFace> project_faces(const ModelMesh& model, const ProfileFrame& frame,
                                         std::optional<double> near, std::optional<double> far,
                                         bool facing_only)
{
    std::vector<ProjectedFace> faces;
    faces.reserve(model.triangles.size());
    for (const auto& t : model.triangles) {
        std::vector<Vec3> polygon{model.vertices[t[0]], model.vertices[t[1]], model.vertices[t[2]]};
        const Vec3 n = (polygon[1] - polygon[0]).cross(polygon[2] - polygon[0]);
        if (facing_only && !(n.dot(frame.normal) > 0))
            continue;
        if (near)
            polygon = cut(polygon, frame.origin, frame.normal, *near, 1.0);
        if (far && polygon.size() >= 3)
            polygon = cut(polygon, frame.origin, frame.normal, *far, -1.0);
        if (polygon.size() < 3)
            continue;
        ProjectedFace face;
        Vec3 centroid = Vec3::Zero();
        for (const Vec3& x : polygon) {
            face.polygon.push_back(frame.to_frame(x));
            centroid += x;
        }
        face.area = std::abs(signed_area(face.polygon));
        if (!(face.area > 1e-12))
            continue; // seen edge-on
        face.depth = (centroid / double(polygon.size()) - frame.origin).dot(frame.normal);
        faces.push_back(std::move(face));
    }
    return faces;
}

Silhouette unite_faces(const std::vector<const ProjectedFace*>& faces, const std::string& name)
{
    // Each face turned counter-clockwise covers its inside with winding +1, so the union is
    // where the winding of all their boundaries together is >= 1. Edges shared by two faces in
    // opposite directions cancel: only the outline of the covered region and where faces overlap
    // is left for Clipper (docs/MATH.md, Profiles and silhouettes). Uniting the triangles
    // themselves is 10x slower into plain paths (bench/silhouette_bench.cpp), and took 3.2 s for
    // 10k faces into a PolyTree.
    using Key = std::pair<ClipperLib::cInt, ClipperLib::cInt>;
    auto key = [](const ClipperLib::IntPoint& p) { return Key(p.X, p.Y); };
    // Every directed edge as (lower end, upper end, +1 or -1), sorted and summed: the net
    // multiplicity of each edge, in the order a map from edge to count would give. A sorted
    // vector is 4x faster than the map on 40k faces (profiled on a subdivided bust scan).
    struct Edge {
        Key from, to;
        int count;
    };
    std::vector<Edge> edges;
    edges.reserve(3 * faces.size());
    ClipperLib::Path path; // one buffer for every face
    for (const ProjectedFace* f : faces) {
        path.clear();
        for (const Vec2& p : f->polygon)
            path.push_back(to_int_point(p));
        if (!ClipperLib::Orientation(path))
            ClipperLib::ReversePath(path);
        for (size_t i = 0, n = path.size(); i < n; ++i) {
            const Key a = key(path[i]), b = key(path[(i + 1) % n]);
            if (a == b)
                continue;
            if (a < b)
                edges.push_back({a, b, 1});
            else
                edges.push_back({b, a, -1});
        }
    }
    // Sorted in two halves, one on each core, then merged: equal edges are summed whatever
    // their order.
    auto before = [](const Edge& x, const Edge& y) {
        return std::tie(x.from, x.to) < std::tie(y.from, y.to);
    };
    const auto middle = edges.begin() + std::ptrdiff_t(edges.size() / 2);
    std::future<void> other =
        std::async(std::launch::async, [&] { std::sort(middle, edges.end(), before); });
    std::sort(edges.begin(), middle, before);
    other.get();
    std::inplace_merge(edges.begin(), middle, edges.end(), before);
    std::map<Key, std::vector<Key>> out; // what is left, as outgoing edges per point
    for (size_t i = 0; i < edges.size();) {
        int count = 0;
        size_t j = i;
        for (; j < edges.size() && edges[j].from == edges[i].from && edges[j].to == edges[i].to;
             ++j)
            count += edges[j].count;
        for (int k = 0; k < std::abs(count); ++k) {
            if (count > 0)
                out[edges[i].from].push_back(edges[i].to);
            else
                out[edges[i].to].push_back(edges[i].from);
        }
        i = j;
    }
    // The edges left form closed walks (as many in as out at every point): follow them.
    ClipperLib::Paths loops;
    for (auto& [start, nexts] : out) {
        while (!nexts.empty()) {
            ClipperLib::Path loop{{start.first, start.second}};
            Key at = nexts.back();
            nexts.pop_back();
            while (at != start) {
                loop.push_back({at.first, at.second});
                std::vector<Key>& from = out[at];
                const Key next = from.back(); // never empty: a boundary is a cycle
                from.pop_back();
                at = next;
            }
            loops.push_back(std::move(loop));
        }
    }
    ClipperLib::Clipper clipper;
    clipper.AddPaths(loops, ClipperLib::ptSubject, true);
    ClipperLib::PolyTree tree;
    clipper.Execute(ClipperLib::ctUnion, tree, ClipperLib::pftPositive, ClipperLib::pftPositive);
    std::vector<Piece> pieces;
    collect(tree, pieces);
    std::stable_sort(pieces.begin(), pieces.end(),
                     [](const Piece& a, const Piece& b) { return a.area > b.area; });
    Silhouette s;
    s.triangles = int(faces.size());
    s.pieces = int(pieces.size());
    s.profile.name = name;
    if (pieces.empty())
        return s;
    s.profile.outer = pieces.front().outer;
    s.profile.holes = pieces.front().holes;
    s.area = pieces.front().area;
    for (size_t k = 1; k < pieces.size(); ++k)
        s.left_out += pieces[k].area;
    return s;
}

} // namespace popup
