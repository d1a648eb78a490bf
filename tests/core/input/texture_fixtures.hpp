#pragma once
// What the texture tests share: the files tools/make_textured_models.py wrote into
// tests/data/textures and a finding's search by code and words.
#include <fstream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "popup/model/result.hpp"

namespace popup::texture_fixtures {

inline const std::string kFolder = "tests/data/textures/";

inline std::string bytes_of(const std::string& path)
{
    std::ifstream file(path, std::ios::binary);
    std::ostringstream bytes;
    bytes << file.rdbuf();
    return bytes.str();
}

/// expected.json: what the script wrote (sizes, probe texels, block colours).
inline nlohmann::json expected()
{
    return nlohmann::json::parse(bytes_of(kFolder + "expected.json"));
}

inline bool has(const Diagnostics& diagnostics, DiagnosticCode code, const std::string& words)
{
    for (const Diagnostic& d : diagnostics)
        if (d.code == code && d.message.find(words) != std::string::npos)
            return true;
    return false;
}

} // namespace popup::texture_fixtures
