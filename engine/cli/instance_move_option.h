// The repeatable `--move NAME X Y Z` option of bounce-render, bounce-trace and bounce-view,
// declared once so the three tools take and describe it alike.
//
// The option only collects the words; the apps turn them into moves with
// parseInstanceMoves (engine/scene/instance_move.h) after loading the scene, inside their own
// error handling, so a bad coordinate or a static instance is reported as "bounce-<tool>:
// error: ..." with exit code 1.
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace bounce {

// Adds `--move NAME X Y Z` (four values each time, repeatable) to `app`; every use appends its
// four words to `words` in command-line order.
CLI::Option* addMoveOption(CLI::App& app, std::vector<std::string>& words);

}  // namespace bounce
