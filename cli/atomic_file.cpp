#include "atomic_file.hpp"

#include <filesystem>
#include <system_error>
#include <unistd.h>

#include "cadmedial/errors.hpp"

namespace cadmedial {

void writeFileAtomically(const std::string& path, const std::function<void(std::ofstream&)>& write, bool binary) {
  namespace fs = std::filesystem;
  const std::string tmp = path + ".tmp." + std::to_string(::getpid());
  try {
    {
      std::ofstream out(tmp, binary ? std::ios::binary | std::ios::trunc : std::ios::trunc);
      if (!out) throw InputError(kExitOutputFailed, "cannot write " + tmp);
      write(out);
      out.flush();
      if (!out) throw InputError(kExitOutputFailed, "write failed for " + path + " (disk full?)");
    }
    std::error_code ec;
    fs::rename(tmp, path, ec);
    if (ec) throw InputError(kExitOutputFailed, "cannot rename " + tmp + " to " + path + ": " + ec.message());
  } catch (...) {
    std::error_code ignored;
    fs::remove(tmp, ignored);
    throw;
  }
}

void createOutputDirectory(const std::string& dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (!ec && !fs::is_directory(dir, ec)) ec = std::make_error_code(std::errc::not_a_directory);
  if (ec) throw InputError(kExitOutputFailed, "cannot create the output folder " + dir + ": " + ec.message());
}

}  // namespace cadmedial
