#include "fluid/mumps_handle.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "common/errors.hpp"

namespace fsi {
namespace {

// A size in INFO(2): negative means millions (MUMPS users' guide, -5, -9, -13, -19).
double entries(int info2) {
  return info2 < 0 ? -1e6 * info2 : info2;
}

std::string count(double n, const char* unit) {
  char text[64];
  std::snprintf(text, sizeof text, "%.3g %s", n, unit);
  return text;
}

std::string words(int info1, int info2) {
  const std::string memory = "not enough memory";
  const std::string workspace = "MUMPS's workspace was too small (ICNTL(14) too low)";
  switch (info1) {
    case -5:
      return memory + " for the analysis (" + count(entries(info2), "reals") +
             " could not be allocated)";
    case -7:
      return memory + " for the analysis (" + count(entries(info2), "integers") +
             " could not be allocated)";
    case -13:
      return memory + " (" + count(entries(info2), "entries") + " could not be allocated)";
    case -19:
      return memory + " within the limit ICNTL(23) (" + count(entries(info2), "entries") +
             " missing)";
    case -6:
      return "the matrix is structurally singular (structural rank " + std::to_string(info2) + ")";
    case -10:
      return "the matrix is numerically singular (" + std::to_string(info2) + " pivots eliminated)";
    case -8:
      return workspace + ": pivoting needed more integer space than the analysis predicted";
    case -9:
      return workspace +
             ": pivoting needed more space for the factors than the analysis predicted (" +
             count(entries(info2), "entries") + " missing)";
    case -14:
    case -15:
      return workspace + " for the solve";
    case -17:
    case -20:
      return workspace + " for an internal message buffer";
    case -11:
    case -12:
      return "MUMPS's internal workspace was too small for the solve (a MUMPS problem)";
    case -16:
      return "the matrix order " + std::to_string(info2) + " is out of range";
    case -2:
      return "the number of matrix entries " + std::to_string(info2) + " is out of range";
    case -4:
      return "the given elimination order is not a permutation (at position " +
             std::to_string(info2) + ")";
    case -22:
      return "an input array is missing or too small (MUMPS's array number " +
             std::to_string(info2) + ")";
    case -3:
      return "MUMPS was called out of order (analysis before factorisation before solve)";
    case -50:
      return "the fill-reducing ordering failed";
    default:
      return "";
  }
}

}  // namespace

std::string mumps_error_words(int info1, int info2) {
  const std::string codes =
      "[INFO(1) = " + std::to_string(info1) + ", INFO(2) = " + std::to_string(info2) + "]";
  const std::string text = words(info1, info2);
  return text.empty() ? codes : text + " " + codes;
}

MumpsHandle::MumpsHandle(std::string who, int sym) : who_(std::move(who)) {
  id_.comm_fortran = -987654;  // MPI_COMM_WORLD of the sequential stub library
  id_.par = 1;
  id_.sym = sym;
  call(-1, "initialisation");
  initialised_ = true;
  icntl(1) = icntl(2) = icntl(3) = -1;  // no output
  icntl(4) = 0;
  icntl(28) = 1;  // sequential analysis
}

MumpsHandle::~MumpsHandle() {
  if (initialised_) {
    id_.job = -2;
    dmumps_c(&id_);
  }
}

void MumpsHandle::call(int job, const char* phase) {
  id_.job = job;
  dmumps_c(&id_);
  check(phase);
}

void MumpsHandle::check(const char* phase) const {
  if (id_.info[0] < 0)
    throw SolverFailure(who_ + phase + " failed: " + mumps_error_words(id_.info[0], id_.info[1]));
}

int MumpsHandle::factorize_numeric() {
  for (int attempt = 0;; ++attempt) {
    if (keep_workspace_) {
      // INFO(8): S's estimated size after the analysis (entries; negative: millions),
      // ICNTL(14)'s margin included; doubled at each retry. LWK_USER counts millions
      // when negative too (a 32-bit integer).
      const double needed = entries(id_.info[7]) * std::pow(2.0, attempt);
      const bool millions = needed > 2e9;
      const double size = millions ? 1e6 * std::ceil(needed / 1e6) : std::ceil(needed);
      if (static_cast<double>(workspace_size_) < size) {
        workspace_.reset();  // the old one freed before the new is allocated
        workspace_size_ = static_cast<std::size_t>(size);
        workspace_ = std::make_unique_for_overwrite<double[]>(workspace_size_);  // MUMPS writes before it reads
      }
      id_.wk_user = workspace_.get();
      const std::size_t have = workspace_size_;
      id_.lwk_user = static_cast<MUMPS_INT>(have > 2000000000 ? -static_cast<long long>(have / 1000000)
                                                                 : static_cast<long long>(have));
    }
    id_.job = 2;
    dmumps_c(&id_);
    const int status = id_.info[0];
    const bool workspace = status == -8 || status == -9 || status == -14 || status == -15 ||
                           status == -17 || status == -20;
    if (!workspace || attempt == 4) return status;
    icntl(14) = std::max(2 * icntl(14), 40);
  }
}

}  // namespace fsi
