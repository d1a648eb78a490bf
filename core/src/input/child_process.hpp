#pragma once
#include <functional>
#include <string>

namespace popup {

/// Runs `work` in a forked child process and returns its bytes in `answer`: assimp's readers
/// loop forever or abort (ai_assert) on some malformed files, which must not take the caller
/// (FreeCAD, the CLI) with them. Returns why not ("" when the child answered): it did not finish
/// within timeout_s (it is killed), it crashed (the signal), or it ended without answering.
/// `answer` may still be a partial message when the child wrote some bytes and then died.
std::string run_in_child(const std::function<std::string()>& work, double timeout_s,
                         std::string& answer);

} // namespace popup
