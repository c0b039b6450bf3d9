#include "deploydyn/output/state_file.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <bit>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string_view>

namespace deploydyn {
namespace {

constexpr std::string_view kMagic = "deploydyn-state\n";
constexpr std::uint32_t kByteOrderMark = 0x01020304;
constexpr std::size_t kHeaderBytes = 16 + 4 + 4 + 3 * 8;

static_assert(std::endian::native == std::endian::little, "states.bin is written little-endian");

template <class T>
void put(std::string& out, T value) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.append(bytes, sizeof(T));
}
void put_doubles(std::string& out, const double* values, std::size_t n) {
  out.append(reinterpret_cast<const char*>(values), n * sizeof(double));
}
void put_vector(std::string& out, const Eigen::VectorXd& v) { put_doubles(out, v.data(), static_cast<std::size_t>(v.size())); }
void put_counted(std::string& out, const std::vector<double>& v) {
  put<std::int64_t>(out, static_cast<std::int64_t>(v.size()));
  put_doubles(out, v.data(), v.size());
}

// Reads from a record's bytes; running past its end is a damaged file.
class Reader {
 public:
  Reader(std::string_view bytes, const std::filesystem::path& file) : bytes_(bytes), file_(file) {}
  template <class T>
  T get() {
    T value;
    std::memcpy(&value, take(sizeof(T)), sizeof(T));
    return value;
  }
  Eigen::VectorXd vector(std::int64_t n) {
    Eigen::VectorXd v(n);
    doubles(v.data(), static_cast<std::size_t>(n));
    return v;
  }
  std::vector<double> counted() {
    const auto n = get<std::int64_t>();
    if (n < 0 || static_cast<std::size_t>(n) > (bytes_.size() - at_) / sizeof(double)) damaged();
    std::vector<double> v(static_cast<std::size_t>(n));
    doubles(v.data(), v.size());
    return v;
  }
  bool done() const { return at_ == bytes_.size(); }

 private:
  // n doubles into `to`, which may be null when n is 0 (an empty vector's data()).
  void doubles(double* to, std::size_t n) {
    const char* from = take(n * sizeof(double));
    if (n > 0) std::memcpy(to, from, n * sizeof(double));
  }
  const char* take(std::size_t n) {
    if (n > bytes_.size() - at_) damaged();
    const char* p = bytes_.data() + at_;
    at_ += n;
    return p;
  }
  [[noreturn]] void damaged() const {
    throw std::invalid_argument(fmt::format("{} is damaged: a record ends early", file_.string()));
  }
  std::string_view bytes_;
  std::size_t at_ = 0;
  const std::filesystem::path& file_;
};

std::string read_all(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::invalid_argument(fmt::format("cannot read {}: {}", file.string(), std::strerror(errno)));
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

struct Parsed {
  StateFileContents contents;
  std::vector<std::string_view> records;  // each record's bytes, after its length
};

Parsed parse(const std::string& bytes, const std::filesystem::path& file) {
  if (bytes.size() < kHeaderBytes || std::string_view(bytes).substr(0, kMagic.size()) != kMagic) {
    throw std::invalid_argument(fmt::format("{} is not a deploydyn state file", file.string()));
  }
  Reader header(std::string_view(bytes).substr(kMagic.size(), kHeaderBytes - kMagic.size()), file);
  const auto version = header.get<std::uint32_t>();
  if (version != kStateFileVersion) {
    throw std::invalid_argument(fmt::format("{} has format version {}; this deploydyn reads version {}",
                                            file.string(), version, kStateFileVersion));
  }
  if (header.get<std::uint32_t>() != kByteOrderMark) {
    throw std::invalid_argument(fmt::format("{} was written with another byte order", file.string()));
  }
  Parsed parsed;
  StateFileUnknowns& u = parsed.contents.unknowns;
  u.n_dofs = header.get<std::int64_t>();
  u.n_equations = header.get<std::int64_t>();
  u.n_history = header.get<std::int64_t>();
  std::size_t at = kHeaderBytes;
  while (bytes.size() - at >= sizeof(std::int64_t)) {
    std::int64_t length;
    std::memcpy(&length, bytes.data() + at, sizeof(length));
    at += sizeof(length);
    if (length < static_cast<std::int64_t>(sizeof(double)) || static_cast<std::size_t>(length) > bytes.size() - at) break;
    const std::string_view record(bytes.data() + at, static_cast<std::size_t>(length));
    at += static_cast<std::size_t>(length);
    double time_s;
    std::memcpy(&time_s, record.data(), sizeof(time_s));
    parsed.contents.times_s.push_back(time_s);
    parsed.records.push_back(record);
  }
  return parsed;
}

}  // namespace

StateFileWriter::StateFileWriter(const std::filesystem::path& file, const StateFileUnknowns& unknowns,
                                 bool every_output)
    : path_(file), unknowns_(unknowns), every_output_(every_output) {
  fd_ = ::open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd_ < 0) throw OutputError("cannot write", path_, errno);
  std::string header(kMagic);
  put<std::uint32_t>(header, kStateFileVersion);
  put<std::uint32_t>(header, kByteOrderMark);
  put<std::int64_t>(header, unknowns.n_dofs);
  put<std::int64_t>(header, unknowns.n_equations);
  put<std::int64_t>(header, unknowns.n_history);
  append(header);
  if (failure_) throw *failure_;
}

StateFileWriter::~StateFileWriter() {
  if (fd_ >= 0) ::close(fd_);
}

void StateFileWriter::keep(const RestartState& s) {
  if (failure_) return;
  const MotionState& m = s.motion;
  std::string body;
  put<double>(body, m.time_s);
  for (const Eigen::VectorXd* v : {&m.q, &m.v, &m.a, &m.pseudo_a}) put_vector(body, *v);
  // The work's forces: empty where the run tracks none (no dissipation).
  for (const Eigen::VectorXd* v : {&s.applied_force_N, &s.lost_force_N}) {
    put_counted(body, std::vector<double>(v->data(), v->data() + v->size()));
  }
  put_vector(body, m.lambda);
  put_vector(body, m.history);
  put<double>(body, s.work.external_J);
  put<double>(body, s.work.dissipated_J);
  put<double>(body, s.steps.step_s);
  put<std::int64_t>(body, s.steps.outputs_written);
  put<std::int64_t>(body, s.calm_since_s ? 1 : 0);
  put<double>(body, s.calm_since_s.value_or(0.0));
  put_counted(body, s.integrator_memory);
  put_counted(body, s.pivot_memory);
  std::string record;
  put<std::int64_t>(record, static_cast<std::int64_t>(body.size()));
  record += body;
  append(record);
}

// One write(2) loop; a failure part-way cuts the file back to its last whole record.
void StateFileWriter::append(const std::string& bytes) {
  std::size_t written = 0;
  while (written < bytes.size()) {
    const ssize_t n = ::write(fd_, bytes.data() + written, bytes.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int error = n < 0 ? errno : ENOSPC;
      if (::ftruncate(fd_, static_cast<off_t>(size_)) == 0) ::lseek(fd_, static_cast<off_t>(size_), SEEK_SET);
      failure_.emplace("cannot write", path_, error);
      return;
    }
    written += static_cast<std::size_t>(n);
  }
  size_ += written;
}

StateFileContents read_state_file_index(const std::filesystem::path& file) {
  return parse(read_all(file), file).contents;
}

RestartState read_state(const std::filesystem::path& file, std::optional<double> time_s) {
  const std::string bytes = read_all(file);
  const Parsed parsed = parse(bytes, file);
  const std::vector<double>& times = parsed.contents.times_s;
  if (times.empty()) throw std::invalid_argument(fmt::format("{} holds no state", file.string()));
  std::size_t which = times.size() - 1;
  if (time_s) {
    which = times.size();
    for (std::size_t i = 0; i < times.size(); ++i) {
      if (times[i] == *time_s) which = i;
    }
    if (which == times.size()) {
      throw std::invalid_argument(fmt::format("{} holds no state at t = {} s", file.string(), *time_s));
    }
  }
  const StateFileUnknowns& u = parsed.contents.unknowns;
  Reader r(parsed.records[which], file);
  RestartState s;
  MotionState& m = s.motion;
  m.time_s = r.get<double>();
  m.q = r.vector(u.n_dofs);
  m.v = r.vector(u.n_dofs);
  m.a = r.vector(u.n_dofs);
  m.pseudo_a = r.vector(u.n_dofs);
  for (Eigen::VectorXd* v : {&s.applied_force_N, &s.lost_force_N}) {
    const std::vector<double> values = r.counted();
    *v = Eigen::Map<const Eigen::VectorXd>(values.data(), static_cast<Eigen::Index>(values.size()));
  }
  m.lambda = r.vector(u.n_equations);
  m.history = r.vector(u.n_history);
  s.work.external_J = r.get<double>();
  s.work.dissipated_J = r.get<double>();
  s.steps.step_s = r.get<double>();
  s.steps.outputs_written = r.get<std::int64_t>();
  const bool calm = r.get<std::int64_t>() != 0;
  const double calm_since_s = r.get<double>();
  if (calm) s.calm_since_s = calm_since_s;
  s.integrator_memory = r.counted();
  s.pivot_memory = r.counted();
  if (!r.done()) throw std::invalid_argument(fmt::format("{} is damaged: a record is longer than its fields", file.string()));
  return s;
}

}  // namespace deploydyn
