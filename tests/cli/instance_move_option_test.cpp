// `--move NAME X Y Z` (engine/cli/instance_move_option.h), the one declaration bounce-render,
// bounce-trace and bounce-view share: four words a use, repeatable, kept in command-line order
// for parseInstanceMoves.
#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/instance_move_option.h"
#include "scene/instance_move.h"

namespace bounce {
namespace {

// Parses `args` (without the program name) with only the --move option declared.
std::vector<std::string> moveWords(std::vector<std::string> args) {
  CLI::App app{"test", "test"};
  std::vector<std::string> words;
  addMoveOption(app, words);
  std::reverse(args.begin(), args.end());  // CLI11 parses a reversed vector from its back
  app.parse(args);
  return words;
}

TEST(MoveOption, EachUseAddsItsFourWordsInCommandLineOrder) {
  const std::vector<std::string> words =
      moveWords({"--move", "ball", "1", "-2.5", "3", "--move", "door", "0", "0.5", "4e-1"});
  EXPECT_EQ(words,
            (std::vector<std::string>{"ball", "1", "-2.5", "3", "door", "0", "0.5", "4e-1"}));
  const std::vector<InstanceMove> moves = parseInstanceMoves(words);
  ASSERT_EQ(moves.size(), 2u);
  EXPECT_EQ(moves[1].name, "door");
  EXPECT_EQ(moves[1].translation, glm::vec3(0.0f, 0.5f, 0.4f));
}

TEST(MoveOption, AbsentLeavesNoMoves) {
  EXPECT_TRUE(moveWords({}).empty());
}

// CLI11 2.1 lets a use end short (and run on into later words); the count is checked once, by
// parseInstanceMoves, inside the tools' error handling ("bounce-<tool>: error: ...", exit 1).
TEST(MoveOption, AShortUseIsRefusedByTheMoveRule) {
  const std::vector<std::string> words = moveWords({"--move", "ball", "1", "2"});
  EXPECT_EQ(words.size(), 3u);
  EXPECT_THROW(parseInstanceMoves(words), std::invalid_argument);
}

}  // namespace
}  // namespace bounce
