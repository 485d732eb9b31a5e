#include "campaign/design_sharing.hpp"

#include <cstdint>
#include <cstring>
#include <span>
#include <stdexcept>

namespace growthuq {
namespace {

// Bytes of a trivially copyable value, appended to and read from a message.
template <class T>
void append_bytes(std::string& message, const T& value) {
  message.append(reinterpret_cast<const char*>(&value), sizeof value);
}

template <class T>
T read_bytes(std::string_view message, std::size_t& at) {
  if (message.size() - at < sizeof(T)) throw std::logic_error("design outline message cut short");
  T value;
  std::memcpy(&value, message.data() + at, sizeof value);
  at += sizeof value;
  return value;
}

}  // namespace

std::string DesignOutline::encode() const {
  std::string message;
  const Eigen::Index m = target_spearman.rows();
  append_bytes(message, static_cast<std::uint64_t>(m));
  for (Eigen::Index a = 0; a < m; ++a) {
    for (Eigen::Index b = 0; b < m; ++b) append_bytes(message, target_spearman(a, b));
  }
  for (const std::string& warning : warnings) {
    append_bytes(message, static_cast<std::uint64_t>(warning.size()));
    message += warning;
  }
  return message;
}

DesignOutline DesignOutline::decode(std::string_view message) {
  DesignOutline outline;
  std::size_t at = 0;
  const auto m = static_cast<Eigen::Index>(read_bytes<std::uint64_t>(message, at));
  outline.target_spearman.resize(m, m);
  for (Eigen::Index a = 0; a < m; ++a) {
    for (Eigen::Index b = 0; b < m; ++b) outline.target_spearman(a, b) = read_bytes<double>(message, at);
  }
  while (at < message.size()) {
    const auto length = static_cast<std::size_t>(read_bytes<std::uint64_t>(message, at));
    if (message.size() - at < length) throw std::logic_error("design outline message cut short");
    outline.warnings.emplace_back(message.substr(at, length));
    at += length;
  }
  return outline;
}

DesignOutline outline_of(const LineDesign& design) {
  DesignOutline outline;
  if (design.target) outline.target_spearman = design.target->target_spearman;
  outline.warnings = design.warnings;
  return outline;
}

void share_design(LineDesign& design, const std::vector<std::string>& names, std::size_t samples, int designer,
                  Pool& pool) {
  const std::size_t columns = names.size();
  const bool mine = pool.rank() == designer;
  if (!mine) {
    design.names = names;
    design.ranks.resize(columns);
    design.values.resize(columns);
    design.strictly_increasing.assign(columns, 0);
  }
  for (std::size_t j = 0; j < columns; ++j) {
    pool.broadcast_vector(design.ranks[j], samples, designer);
    pool.broadcast_vector(design.values[j], samples, designer);
  }
  pool.broadcast_bytes(std::as_writable_bytes(std::span(design.strictly_increasing)), designer);

  std::string message = mine ? outline_of(design).encode() : std::string();
  std::uint64_t size = message.size();
  pool.broadcast_bytes(std::as_writable_bytes(std::span(&size, 1)), designer);
  message.resize(size);
  pool.broadcast_bytes(std::as_writable_bytes(std::span(message.data(), message.size())), designer);
  if (mine) return;
  DesignOutline outline = DesignOutline::decode(message);
  if (outline.target_spearman.rows() > 0) {
    ImanConoverTarget target;
    target.names = design.names;
    target.target_spearman = std::move(outline.target_spearman);
    design.target = std::move(target);
  }
  design.warnings = std::move(outline.warnings);
}

}  // namespace growthuq
