#pragma once
// Base64 (RFC 4648, padded): bytes inside text — data: URIs of a report
// page, the binary data of the web page's script.
#include <string>
#include <vector>

namespace stochtex {

std::string base64(const std::vector<unsigned char>& bytes);

}  // namespace stochtex
