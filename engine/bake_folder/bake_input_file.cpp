#include "bake_folder/bake_input_file.h"

#include <stdexcept>
#include <string>

#include "io/load_error.h"

namespace bounce {

std::vector<unsigned char> readBakeInputFile(const std::filesystem::path& file,
                                             std::size_t maxBytes) {
  if (!std::filesystem::exists(file)) throw LoadError(file, "missing");
  try {
    return readRegularFile(file, maxBytes);
  } catch (const std::runtime_error& e) {
    // readRegularFile says "<file>: <reason>"; LoadError adds the file itself.
    std::string why = e.what();
    const std::string prefix = file.string() + ": ";
    if (why.starts_with(prefix)) why.erase(0, prefix.size());
    throw LoadError(file, why);
  }
}

}  // namespace bounce
