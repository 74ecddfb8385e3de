// SPDX-License-Identifier: MIT
// Atomic file replacement (write a temporary, then rename).
#include "common/io/atomic_file.hpp"

#include <unistd.h>

#include <fstream>
#include <stdexcept>

#include <fmt/format.h>

namespace hs::common {

void write_file_atomic(const std::filesystem::path& file, const std::function<void(std::ostream&)>& writer) {
  const std::filesystem::path tmp = file.string() + fmt::format(".tmp{}", ::getpid());
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error(fmt::format("cannot write {}", tmp.string()));
    writer(out);
    out.flush();
    if (!out) throw std::runtime_error(fmt::format("write failed: {}", tmp.string()));
  }
  std::filesystem::rename(tmp, file);   // atomic on POSIX within one file system
}

void write_file_atomic(const std::filesystem::path& file, std::string_view content) {
  write_file_atomic(file, [content](std::ostream& out) { out.write(content.data(), static_cast<std::streamsize>(content.size())); });
}

}  // namespace hs::common
