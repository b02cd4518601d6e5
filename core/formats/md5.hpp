// MD5 message digest (RFC 1321), for the checksums an .x3p archive carries; not used for security.
#pragma once

#include <string>
#include <string_view>

namespace contactbench::formats {

// The digest of `data` as 32 lower-case hexadecimal digits.
std::string md5_hex(std::string_view data);

}  // namespace contactbench::formats
