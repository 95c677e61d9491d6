#include "cli/instance_move_option.h"

namespace bounce {

CLI::Option* addMoveOption(CLI::App& app, std::vector<std::string>& words) {
  return app
      .add_option("--move", words,
                  "NAME X Y Z: place the dynamic instance NAME (glTF node name, extras.bounce."
                  "mobility = dynamic) with its world translation at (X, Y, Z) metres; "
                  "repeatable. bounce-render, bounce-trace and bounce-view place it the same way")
      ->expected(4)
      // Exactly four words per use: without it CLI11 2.1 lets a use take the words after it
      // (`--move b 1 2 3 scene.gltf` swallowed the scene path).
      ->allow_extra_args(false)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
}

}  // namespace bounce
