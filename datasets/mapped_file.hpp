#pragma once

#include <cstddef>
#include <filesystem>
#include <span>

namespace radarpr {

// A whole file mapped read-only into memory (POSIX mmap), unmapped when destroyed. Pages are read
// from the file when first touched, so mapping a file costs nothing until its bytes are used, and
// release() lets go of pages already used: a process reading a large file a block at a time holds
// one block in memory, not the file. The mapping keeps the file it opened: an entry renamed over
// it meanwhile (how radarpr replaces files) does not change what it reads. A file truncated by
// another process while mapped is the one thing it cannot survive (the access would fault);
// radarpr never truncates a file in place.
class MappedFile {
 public:
  MappedFile() = default;
  // Throws std::runtime_error naming `path` and the cause when it cannot be opened or mapped.
  // An empty file maps to no bytes.
  explicit MappedFile(const std::filesystem::path& path);
  MappedFile(MappedFile&& other) noexcept;
  MappedFile& operator=(MappedFile&& other) noexcept;
  MappedFile(const MappedFile&) = delete;
  MappedFile& operator=(const MappedFile&) = delete;
  ~MappedFile();

  std::span<const std::byte> bytes() const { return {data_, size_}; }
  std::size_t size() const { return size_; }
  const std::filesystem::path& path() const { return path_; }

  // Drops the pages of bytes [offset, offset + length) from this process's memory (the whole
  // pages inside that range); reading them again reads them from the file again. Only a hint.
  void release(std::size_t offset, std::size_t length) const;

 private:
  void unmap() noexcept;

  std::filesystem::path path_;
  const std::byte* data_ = nullptr;
  std::size_t size_ = 0;
};

}  // namespace radarpr
