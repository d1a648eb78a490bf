#pragma once
#include <string>
#include <utility>
#include <vector>

namespace popup {

/// One finding a person can act on: a stable machine code, a sentence, and the thing it is about
/// (a patch, hinge or file field).
struct Diagnostic {
    std::string code;
    std::string message;
    std::string subject;
};

using Diagnostics = std::vector<Diagnostic>;

/// A value plus the diagnostics gathered while computing it. `ok` is false when the value must
/// not be trusted (the diagnostics then say why).
template <class T> struct Result {
    T value{};
    bool ok = true;
    Diagnostics diagnostics;

    void fail(std::string code, std::string message, std::string subject = {})
    {
        ok = false;
        diagnostics.push_back({std::move(code), std::move(message), std::move(subject)});
    }
    /// Fails with the diagnostics of a step that failed.
    void fail_with(const Diagnostics& why)
    {
        ok = false;
        diagnostics = why;
    }
    void warn(std::string code, std::string message, std::string subject = {})
    {
        diagnostics.push_back({std::move(code), std::move(message), std::move(subject)});
    }
};

} // namespace popup
