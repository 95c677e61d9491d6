// bounce-bake merge PART_1 … PART_N -o DIR: the bake folder from the parts of a sharded bake
// (bounce-bake SCENE -o PART_K --shard K/N), the same bytes as one process's bake.
#pragma once

namespace bounce {

// argv[0] is "merge". Returns the exit code.
int bakeMergeMain(int argc, char** argv);

}  // namespace bounce
