#ifndef hati_base_fnv_hash_h
#define hati_base_fnv_hash_h

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>

namespace hati
{
/** The FNV-1a offset basis: the hash of no bytes. */
constexpr std::uint64_t fnv1a64_basis = 14695981039346656037ull;

/**
 * FNV-1a, 64 bits, of @p bytes bytes at @p data, continuing from @p hash.
 * Each step is a bijection of the hash for a given byte, so any one byte
 * changed changes the result: the checksum of a state file (state.bin)
 * and the digests of input files, not a cryptographic hash.
 */
inline std::uint64_t
fnv1a64(const void *data, const std::size_t bytes, std::uint64_t hash = fnv1a64_basis)
{
  const auto *b = static_cast<const unsigned char *>(data);
  for (std::size_t i = 0; i < bytes; ++i)
    hash = (hash ^ b[i]) * 1099511628211ull;
  return hash;
}

/** fnv1a64() of @p text. */
inline std::uint64_t fnv1a64(const std::string &text, std::uint64_t hash = fnv1a64_basis)
{
  return fnv1a64(text.data(), text.size(), hash);
}

/** @p hash as 16 lower-case hexadecimal digits. */
inline std::string hex_digits(const std::uint64_t hash)
{
  char hex[17];
  std::snprintf(hex, sizeof(hex), "%016llx", static_cast<unsigned long long>(hash));
  return hex;
}

/**
 * `fnv1a64 <16 hex digits>, <size> bytes` of the file @p path, or
 * `missing` if it cannot be read (the caller checks regular files first).
 */
inline std::string file_digest(const std::string &path)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
    return "missing";
  std::uint64_t hash = fnv1a64_basis, size = 0;
  char block[1 << 16];
  while (in && (in.read(block, sizeof(block)), in.gcount() > 0))
  {
    hash = fnv1a64(block, in.gcount(), hash);
    size += in.gcount();
  }
  if (in.bad())
    return "missing";
  return "fnv1a64 " + hex_digits(hash) + ", " + std::to_string(size) + " bytes";
}
} // namespace hati

#endif
