#include "io/checkpoint.hpp"

#include <cstring>
#include <fstream>
#include <sstream>

#include "common/errors.hpp"
#include "io/atomic_file.hpp"

namespace fsi {
namespace {

constexpr const char* kMagic = "fsicontact checkpoint 1";
constexpr long kMaxEntries = 100000;
constexpr long kMaxDoubles = 1L << 31;  // 16 GiB of state: far beyond any case a checkpoint serves

std::uint64_t fnv1a(const char* data, std::size_t n) {
  std::uint64_t h = 1469598103934665603ull;
  for (std::size_t i = 0; i < n; ++i) h = (h ^ static_cast<unsigned char>(data[i])) * 1099511628211ull;
  return h;
}

[[noreturn]] void refuse(const std::string& path, const std::string& why) {
  throw InputError(path + ": not a checkpoint of fsicontact (" + why + "); --resume takes the output directory of a "
                   "time run, which holds " + checkpoint_file_name());
}

std::string read_all(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot read the checkpoint: " + std::strerror(errno));
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The header's next line, or refuse.
std::string next_line(std::istringstream& header, const std::string& path) {
  std::string line;
  if (!std::getline(header, line)) refuse(path, "its header ends early");
  return line;
}

}  // namespace

std::string fnv1a_hex(const std::string& bytes) {
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(fnv1a(bytes.data(), bytes.size())));
  return hex;
}

void Checkpoint::put(const std::string& name, const Eigen::VectorXd& values) {
  if (!arrays_.count(name)) order.push_back(name);
  arrays_[name] = values;
}

void Checkpoint::put_matrix(const std::string& name, const Eigen::MatrixXd& values) {
  put(name + ".rows", double(values.rows()));
  put(name + ".cols", double(values.cols()));
  put(name, Eigen::VectorXd(values.reshaped()));
}

void Checkpoint::put_ints(const std::string& name, const std::vector<int>& values) {
  Eigen::VectorXd v(static_cast<long>(values.size()));
  for (std::size_t i = 0; i < values.size(); ++i) v[static_cast<long>(i)] = values[i];
  put(name, v);
}

const Eigen::VectorXd& Checkpoint::vector(const std::string& name, long size) const {
  const auto it = arrays_.find(name);
  const std::string where = (source.empty() ? std::string("the checkpoint") : source) + ": ";
  if (it == arrays_.end()) throw InputError(where + "the checkpoint has no '" + name + "' (written by another kind of run?)");
  if (size >= 0 && it->second.size() != size)
    throw InputError(where + "'" + name + "' has " + std::to_string(it->second.size()) + " values where this case has " +
                     std::to_string(size) + " (a checkpoint of another mesh?)");
  return it->second;
}

int Checkpoint::integer(const std::string& name) const {
  const double x = scalar(name);
  if (!(x >= -2147483648.0 && x <= 2147483647.0) || x != double(int(x)))
    throw InputError(source + ": '" + name + "' is not an integer in the checkpoint");
  return int(x);
}

Eigen::MatrixXd Checkpoint::matrix(const std::string& name) const {
  const int rows = integer(name + ".rows"), cols = integer(name + ".cols");
  if (rows < 0 || cols < 0) throw InputError(source + ": '" + name + "' has a negative shape in the checkpoint");
  return vector(name, long(rows) * cols).reshaped(rows, cols);
}

std::vector<int> Checkpoint::ints(const std::string& name) const {
  const Eigen::VectorXd& v = vector(name);
  std::vector<int> out(static_cast<std::size_t>(v.size()));
  for (long i = 0; i < v.size(); ++i) {
    if (v[i] != double(int(v[i]))) throw InputError(source + ": '" + name + "' holds a non-integer in the checkpoint");
    out[static_cast<std::size_t>(i)] = int(v[i]);
  }
  return out;
}

void write_checkpoint(const std::string& path, const Checkpoint& c) {
  std::ostringstream header;
  char t[40];
  std::snprintf(t, sizeof t, "%a", c.t);  // hexadecimal: the time's every bit
  header << kMagic << "\nkind " << c.kind << "\nfingerprint " << c.fingerprint << "\nstep " << c.step << "\nt " << t
         << "\narrays " << c.order.size() << "\n";
  std::string data;
  for (const std::string& name : c.order) {
    const Eigen::VectorXd& v = c.arrays().at(name);
    header << name << " " << v.size() << "\n";
    if (v.size() > 0) data.append(reinterpret_cast<const char*>(v.data()), sizeof(double) * static_cast<std::size_t>(v.size()));
  }
  const std::uint64_t sum = fnv1a(data.data(), data.size());
  header << "data\n";
  std::string bytes = header.str() + data;
  bytes.append(reinterpret_cast<const char*>(&sum), sizeof sum);
  write_file_atomically(path, bytes);
}

Checkpoint read_checkpoint(const std::string& path) {
  const std::string bytes = read_all(path);
  const std::size_t end = bytes.find("\ndata\n");
  if (bytes.compare(0, std::strlen(kMagic), kMagic) != 0 || end == std::string::npos)
    refuse(path, "it does not begin as one");
  std::istringstream header(bytes.substr(0, end + 1));
  Checkpoint c;
  c.source = path;
  next_line(header, path);
  const auto field = [&](const char* key) {
    const std::string line = next_line(header, path), prefix = std::string(key) + " ";
    if (line.compare(0, prefix.size(), prefix) != 0) refuse(path, std::string("no '") + key + "' line");
    return line.substr(prefix.size());
  };
  c.kind = field("kind");
  c.fingerprint = field("fingerprint");
  try {
    c.step = std::stoi(field("step"));
    c.t = std::strtod(field("t").c_str(), nullptr);
    const long count = std::stol(field("arrays"));
    if (count < 0 || count > kMaxEntries) refuse(path, "an impossible number of arrays");
    std::vector<std::pair<std::string, long>> sizes;
    long total = 0;
    for (long i = 0; i < count; ++i) {
      const std::string line = next_line(header, path);
      const std::size_t space = line.rfind(' ');
      const long n = space == std::string::npos ? -1 : std::stol(line.substr(space + 1));
      if (n < 0 || n > kMaxDoubles - total) refuse(path, "an array of impossible size");
      sizes.emplace_back(line.substr(0, space), n), total += n;
    }
    const std::size_t data_at = end + 6, data_bytes = sizeof(double) * static_cast<std::size_t>(total);
    if (bytes.size() != data_at + data_bytes + sizeof(std::uint64_t)) refuse(path, "its size does not match its header: truncated?");
    std::uint64_t sum;
    std::memcpy(&sum, bytes.data() + data_at + data_bytes, sizeof sum);
    if (sum != fnv1a(bytes.data() + data_at, data_bytes)) refuse(path, "its checksum does not match: altered or damaged");
    std::size_t at = data_at;
    for (const auto& [name, n] : sizes) {
      Eigen::VectorXd v(n);
      // An empty Eigen vector's data() is null, which memcpy may not take even for 0 bytes.
      if (n > 0) std::memcpy(v.data(), bytes.data() + at, sizeof(double) * static_cast<std::size_t>(n));
      at += sizeof(double) * static_cast<std::size_t>(n);
      c.put(name, v);
    }
  } catch (const std::logic_error&) {  // std::stoi / stol on a line that is no number
    refuse(path, "a header line that is no number");
  }
  return c;
}

}  // namespace fsi
