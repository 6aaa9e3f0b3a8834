// fsicontact command line (app/cli.cpp): no numerics here.
#include <iostream>

#include "cli.hpp"

int main(int argc, char** argv) {
  try {
    return fsi::fsicontact_main(argc, argv, std::cout, std::cerr);
  } catch (const std::exception& e) {  // a bug of ours: say so, exit 1
    std::cerr << "fsicontact: internal error: " << e.what() << std::endl;
    return 1;
  }
}
