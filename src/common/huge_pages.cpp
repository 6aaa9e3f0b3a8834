#include "common/huge_pages.hpp"

#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <iterator>

namespace fsi {
namespace {

constexpr const char* kTunable = "glibc.malloc.hugetlb=1";

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kSanitized = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kSanitized = true;
#else
constexpr bool kSanitized = false;
#endif
#else
constexpr bool kSanitized = false;
#endif

}  // namespace

std::string thp_mode() {
  std::ifstream in("/sys/kernel/mm/transparent_hugepage/enabled");
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

bool wants_huge_page_restart(const char* tunables, const std::string& mode) {
  return tunables == nullptr && mode.find("[madvise]") != std::string::npos;
}

bool uses_huge_pages() {
  const std::string mode = thp_mode();
  if (mode.find("[always]") != std::string::npos) return true;
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  return mode.find("[madvise]") != std::string::npos && tunables &&
         std::string(tunables).find(kTunable) != std::string::npos;
}

bool sanitized_allocator() { return kSanitized; }

void restart_with_huge_pages(char** argv) {
  if (kSanitized || !wants_huge_page_restart(std::getenv("GLIBC_TUNABLES"), thp_mode())) return;
  if (setenv("GLIBC_TUNABLES", kTunable, 1) != 0) return;
  execv("/proc/self/exe", argv);
  unsetenv("GLIBC_TUNABLES");  // not started again: as if never asked
}

}  // namespace fsi
