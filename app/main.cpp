// fsicontact command line (app/cli.cpp): no numerics here.
#include <iostream>

#include "cli.hpp"
#include "common/huge_pages.hpp"

int main(int argc, char** argv) {
  fsi::restart_with_huge_pages(argv);  // first: glibc reads its tunables at start only
  try {
    return fsi::fsicontact_main(argc, argv, std::cout, std::cerr);
  } catch (const std::exception& e) {  // a bug of ours: say so, exit 1
    std::cerr << "fsicontact: internal error: " << e.what() << std::endl;
    return 1;
  }
}
