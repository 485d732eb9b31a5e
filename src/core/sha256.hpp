// SHA-256 (FIPS 180-4) of a byte string, as lowercase hex: the hash `sha256sum` prints, so a
// reader of a run's provenance can check which campaign file produced the results.
#pragma once

#include <string>
#include <string_view>

namespace growthuq {

// 64 lowercase hex digits.
std::string sha256_hex(std::string_view bytes);

}  // namespace growthuq
