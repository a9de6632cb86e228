/**
 * \file
 * \brief The digests and encodings IP cameras authenticate with (OpenSSL's libcrypto): MD5 for HTTP Digest, SHA-1 and
 * Base64 for WS-Security's UsernameToken PasswordDigest, hex digits for digests and certificate fingerprints.
 */
#pragma once

#include <cstddef>
#include <string>

namespace ptz_action_server
{
/// \p count bytes as lower-case hex digits, two a byte.
std::string hexDigits(const unsigned char* bytes, std::size_t count);
/// MD5 of \p text as 32 lower-case hex digits.
std::string md5Hex(const std::string& text);
/// The 20 raw bytes of SHA-1 of \p bytes.
std::string sha1(const std::string& bytes);
/// Standard Base64 with padding.
std::string base64Encode(const std::string& bytes);
/// Decodes standard Base64 (padding required); false for anything else.
bool base64Decode(const std::string& text, std::string& bytes);
/// \p count bytes from OpenSSL's CSPRNG (RAND_bytes: seeded by the operating system), for nonces no one can guess
/// or see repeat. Throws std::runtime_error if it has no entropy to give.
std::string randomBytes(std::size_t count);

}  // namespace ptz_action_server
