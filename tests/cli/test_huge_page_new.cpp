// cli/huge_page_new.cpp: the executable's operator new asks the kernel for
// huge pages on large blocks (madvise MADV_HUGEPAGE), which the kernel shows
// as the flag "hg" in /proc/self/smaps' VmFlags of the mapping holding them.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>

namespace {

bool hugePagesOptedOut() {
  const char* setting = std::getenv("CADMEDIAL_HUGE_PAGES");
  return setting && std::strcmp(setting, "0") == 0;
}

// The VmFlags of the mapping that holds `address`, or nothing without
// /proc/self/smaps or a kernel without transparent huge pages.
std::optional<std::string> flagsOfMappingAt(const void* address) {
  if (!std::ifstream("/sys/kernel/mm/transparent_hugepage/enabled")) return std::nullopt;
  std::ifstream smaps("/proc/self/smaps");
  if (!smaps) return std::nullopt;
  const auto at = reinterpret_cast<std::uintptr_t>(address);
  bool inside = false;
  std::string line;
  while (std::getline(smaps, line)) {
    std::uintptr_t begin = 0, end = 0;
    char dash = 0;
    std::istringstream head(line);
    if (head >> std::hex >> begin >> dash >> end && dash == '-' && line.find(':') > line.find(' ')) {
      inside = begin <= at && at < end;
      continue;
    }
    if (inside && line.rfind("VmFlags:", 0) == 0) return line;
  }
  return std::nullopt;
}

// Address of the first 2 MiB boundary inside the block.
const void* firstHugePageIn(const char* block) {
  constexpr std::uintptr_t kHugePage = std::uintptr_t(2) << 20;
  return reinterpret_cast<const void*>((reinterpret_cast<std::uintptr_t>(block) + kHugePage - 1) & ~(kHugePage - 1));
}

bool hasHugePageAdvice(const std::string& flags) { return flags.find(" hg") != std::string::npos; }

}  // namespace

TEST(HugePageNew, LargeBlocksAreAdvised) {
  if (hugePagesOptedOut()) GTEST_SKIP() << "CADMEDIAL_HUGE_PAGES=0";
  const std::unique_ptr<char[]> large(new char[std::size_t(16) << 20]);
  const std::optional<std::string> flags = flagsOfMappingAt(firstHugePageIn(large.get()));
  if (!flags) GTEST_SKIP() << "no /proc/self/smaps or no transparent huge pages here";
  EXPECT_TRUE(hasHugePageAdvice(*flags)) << *flags;
}

TEST(HugePageNew, OptOutGivesNoAdvice) {
  if (!hugePagesOptedOut()) GTEST_SKIP() << "run by ctest with CADMEDIAL_HUGE_PAGES=0";
  // glibc advises every block itself under this tunable.
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  if (tunables && std::strstr(tunables, "glibc.malloc.hugetlb")) GTEST_SKIP() << "GLIBC_TUNABLES asks glibc for huge pages";
  // A block of its own mapping (above malloc's mmap threshold), so no other
  // block's advice can be on it.
  const std::unique_ptr<char[]> large(new char[std::size_t(64) << 20]);
  const std::optional<std::string> flags = flagsOfMappingAt(firstHugePageIn(large.get()));
  if (!flags) GTEST_SKIP() << "no /proc/self/smaps or no transparent huge pages here";
  EXPECT_FALSE(hasHugePageAdvice(*flags)) << *flags;
}
