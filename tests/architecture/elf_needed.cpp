#include "elf_needed.hpp"

#include <elf.h>

#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>

namespace radarpr::test {
namespace {

// A T at `offset` of `bytes`, or an error naming `path` when the file is shorter.
template <typename T>
T read_at(const std::vector<char>& bytes, std::uint64_t offset, const std::filesystem::path& path) {
  if (offset > bytes.size() || bytes.size() - offset < sizeof(T)) {
    throw std::runtime_error(path.string() + ": truncated ELF file");
  }
  T value;
  std::memcpy(&value, bytes.data() + offset, sizeof(T));
  return value;
}

}  // namespace

std::vector<std::string> elf_needed_libraries(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw std::runtime_error(path.string() + ": cannot read it");
  const std::vector<char> bytes((std::istreambuf_iterator<char>(file)),
                                std::istreambuf_iterator<char>());
  const auto header = read_at<Elf64_Ehdr>(bytes, 0, path);
  if (std::memcmp(header.e_ident, ELFMAG, SELFMAG) != 0 || header.e_ident[EI_CLASS] != ELFCLASS64 ||
      header.e_ident[EI_DATA] != ELFDATA2LSB) {
    throw std::runtime_error(path.string() + ": not a 64-bit little-endian ELF file");
  }
  auto section = [&](std::uint64_t index) {
    if (index >= header.e_shnum) throw std::runtime_error(path.string() + ": bad section index");
    return read_at<Elf64_Shdr>(bytes, header.e_shoff + index * header.e_shentsize, path);
  };
  std::vector<std::string> needed;
  bool found_dynamic = false;
  for (std::uint64_t index = 0; index < header.e_shnum; ++index) {
    const Elf64_Shdr dynamic = section(index);
    if (dynamic.sh_type != SHT_DYNAMIC) continue;
    found_dynamic = true;
    const Elf64_Shdr strings = section(dynamic.sh_link);  // the dynamic string table
    for (std::uint64_t at = 0; at + sizeof(Elf64_Dyn) <= dynamic.sh_size; at += sizeof(Elf64_Dyn)) {
      const auto entry = read_at<Elf64_Dyn>(bytes, dynamic.sh_offset + at, path);
      if (entry.d_tag == DT_NULL) break;
      if (entry.d_tag != DT_NEEDED) continue;
      const std::uint64_t name = strings.sh_offset + entry.d_un.d_val;
      if (name >= bytes.size() || entry.d_un.d_val >= strings.sh_size) {
        throw std::runtime_error(path.string() + ": DT_NEEDED name outside its string table");
      }
      needed.emplace_back(bytes.data() + name, strnlen(bytes.data() + name, bytes.size() - name));
    }
  }
  if (!found_dynamic) throw std::runtime_error(path.string() + ": no dynamic section");
  return needed;
}

}  // namespace radarpr::test
