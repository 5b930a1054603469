#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace radarpr::test {

// The libraries an ELF file names as needed (its dynamic section's DT_NEEDED entries), in order:
// what the dynamic loader loads with it at every start. Reads 64-bit little-endian ELF files
// through their section headers; throws std::runtime_error naming the file when it is not one.
std::vector<std::string> elf_needed_libraries(const std::filesystem::path& path);

}  // namespace radarpr::test
