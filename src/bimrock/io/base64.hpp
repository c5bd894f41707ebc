#pragma once
/// @file Base64 (RFC 4648, section 4: the standard alphabet, '=' padding): how VTK's XML files
/// carry binary arrays inline (vtk_writer.hpp).
#include <cstddef>
#include <string>

namespace bimrock {

/// Appends the Base64 encoding of `size` bytes to `out`.
void append_base64(std::string& out, const void* bytes, std::size_t size);

}  // namespace bimrock
