#include "text_coordinates.hpp"

#include <algorithm>
#include <cctype>
#include <cfloat>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

namespace popup {

namespace {

std::string lower(std::string text)
{
    std::transform(text.begin(), text.end(), text.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return text;
}

std::vector<std::string> tokens_of(const std::string& line)
{
    std::istringstream in(line);
    std::vector<std::string> out;
    for (std::string token; in >> token;)
        out.push_back(token);
    return out;
}

/// A number strtod reads as NaN or infinite, or too large for a float; words that are no number
/// at all (OBJ's optional weights are numbers too) are not judged here.
bool non_finite(const std::string& token)
{
    const char* begin = token.c_str();
    char* end = nullptr;
    const double value = std::strtod(begin, &end);
    if (end == begin)
        return false;
    return !std::isfinite(value) || std::abs(value) > double(FLT_MAX);
}

/// Reads the file line by line; `visit(line_number, tokens)` returns false to stop.
template <class Visit> void each_line(std::ifstream& in, long& number, Visit&& visit)
{
    for (std::string line; std::getline(in, line);) {
        ++number;
        if (!visit(tokens_of(line)))
            return;
    }
}

/// Coordinates `columns` (x, y, z order) of a vertex line, judged in turn.
std::optional<NonFiniteCoordinate> judge(const std::vector<std::string>& tokens,
                                         const int (&columns)[3], long line, long vertex)
{
    for (int axis = 0; axis < 3; ++axis) {
        const int c = columns[axis];
        if (c >= 0 && c < int(tokens.size()) && non_finite(tokens[c]))
            return NonFiniteCoordinate{line, vertex, char('x' + axis), tokens[c]};
    }
    return std::nullopt;
}

/// OBJ "v x y z [w]" and ASCII STL "vertex x y z": every line with that first word.
std::optional<NonFiniteCoordinate> scan_keyword(std::ifstream& in, const std::string& keyword)
{
    static const int columns[3] = {1, 2, 3};
    std::optional<NonFiniteCoordinate> found;
    long number = 0, vertex = 0;
    each_line(in, number, [&](const std::vector<std::string>& t) {
        if (t.empty() || t[0] != keyword)
            return true;
        found = judge(t, columns, number, vertex++);
        return !found;
    });
    return found;
}

/// ASCII PLY: the header names the elements in file order, one line per item after it.
std::optional<NonFiniteCoordinate> scan_ply(std::ifstream& in)
{
    struct Element {
        std::string name;
        long count = 0;
        std::vector<std::string> properties;
    };
    std::vector<Element> elements;
    bool ascii = false;
    long number = 0;
    bool header_done = false;
    each_line(in, number, [&](const std::vector<std::string>& t) {
        if (t.empty())
            return true;
        if (t[0] == "format")
            ascii = t.size() > 1 && t[1] == "ascii";
        else if (t[0] == "element" && t.size() > 2)
            elements.push_back({t[1], std::atol(t[2].c_str()), {}});
        else if (t[0] == "property" && !elements.empty())
            elements.back().properties.push_back(t.back());
        else if (t[0] == "end_header") {
            header_done = true;
            return false;
        }
        return true;
    });
    if (!ascii || !header_done)
        return std::nullopt;
    long skip = 0; // item lines of the elements before the vertices
    for (const Element& e : elements) {
        if (e.name != "vertex") {
            skip += std::max(0L, e.count);
            continue;
        }
        if (e.count <= 0)
            return std::nullopt;
        int columns[3] = {-1, -1, -1};
        for (size_t p = 0; p < e.properties.size(); ++p)
            for (int axis = 0; axis < 3; ++axis)
                if (e.properties[p] == std::string(1, char('x' + axis)))
                    columns[axis] = int(p);
        std::optional<NonFiniteCoordinate> found;
        long item = 0;
        each_line(in, number, [&](const std::vector<std::string>& t) {
            if (t.empty())
                return true;
            if (skip > 0) {
                --skip;
                return true;
            }
            found = judge(t, columns, number, item);
            return !found && ++item < e.count;
        });
        return found;
    }
    return std::nullopt;
}

/// OFF: "[ST][C][N][4][n]OFF", then vertex, face and edge counts, then one vertex a line;
/// '#' starts a comment.
std::optional<NonFiniteCoordinate> scan_off(std::ifstream& in)
{
    static const int columns[3] = {0, 1, 2};
    long number = 0, vertices = -1, vertex = 0;
    bool keyword = false;
    std::optional<NonFiniteCoordinate> found;
    each_line(in, number, [&](std::vector<std::string> t) {
        const auto comment =
            std::find_if(t.begin(), t.end(), [](const std::string& s) { return s[0] == '#'; });
        t.erase(comment, t.end());
        if (t.empty())
            return true;
        if (!keyword) {
            keyword = true;
            if (t[0].size() < 3 || t[0].compare(t[0].size() - 3, 3, "OFF") != 0)
                return false; // not an OFF file
            t.erase(t.begin());
            if (t.empty())
                return true;
        }
        if (vertices < 0) {
            vertices = std::atol(t[0].c_str());
            return vertices > 0;
        }
        found = judge(t, columns, number, vertex);
        return !found && ++vertex < vertices;
    });
    return found;
}

} // namespace

std::optional<NonFiniteCoordinate> find_non_finite_coordinate(const std::string& path)
{
    const std::string extension = lower(std::filesystem::path(path).extension().string());
    std::ifstream in(path, std::ios::binary);
    if (!in)
        return std::nullopt;
    if (extension == ".obj")
        return scan_keyword(in, "v");
    if (extension == ".stl") {
        // Binary STL has an 80-byte header that may start with "solid" too; its vertices are
        // float bits that check_model judges, and a text "vertex" line is vanishingly unlikely.
        return scan_keyword(in, "vertex");
    }
    if (extension == ".ply")
        return scan_ply(in);
    if (extension == ".off")
        return scan_off(in);
    return std::nullopt;
}

} // namespace popup
