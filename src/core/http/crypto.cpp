#include "ptz_action_server/core/http/crypto.h"

#include <openssl/evp.h>
#include <openssl/rand.h>

#include <stdexcept>

namespace ptz_action_server
{
namespace
{
std::string digest(const EVP_MD* type, const std::string& bytes)
{
  unsigned char out[EVP_MAX_MD_SIZE];
  unsigned int size = 0;
  EVP_Digest(bytes.data(), bytes.size(), out, &size, type, nullptr);
  return std::string(reinterpret_cast<const char*>(out), size);
}
}  // namespace

std::string hexDigits(const unsigned char* bytes, std::size_t count)
{
  static const char* const DIGITS = "0123456789abcdef";
  std::string hex;
  hex.reserve(2 * count);
  for (std::size_t index = 0; index < count; ++index)
  {
    hex += DIGITS[bytes[index] >> 4];
    hex += DIGITS[bytes[index] & 0x0f];
  }
  return hex;
}

std::string md5Hex(const std::string& text)
{
  const std::string raw = digest(EVP_md5(), text);
  return hexDigits(reinterpret_cast<const unsigned char*>(raw.data()), raw.size());
}

std::string sha1(const std::string& bytes)
{
  return digest(EVP_sha1(), bytes);
}

std::string base64Encode(const std::string& bytes)
{
  std::string text(4 * ((bytes.size() + 2) / 3) + 1, '\0');
  const int size =
      EVP_EncodeBlock(reinterpret_cast<unsigned char*>(&text[0]), reinterpret_cast<const unsigned char*>(bytes.data()),
                      static_cast<int>(bytes.size()));
  text.resize(static_cast<std::size_t>(size));
  return text;
}

bool base64Decode(const std::string& text, std::string& bytes)
{
  if (text.size() % 4 != 0)
  {
    return false;
  }
  bytes.assign(3 * text.size() / 4 + 1, '\0');
  const int size = EVP_DecodeBlock(reinterpret_cast<unsigned char*>(&bytes[0]),
                                   reinterpret_cast<const unsigned char*>(text.data()), static_cast<int>(text.size()));
  if (size < 0)
  {
    return false;
  }
  // EVP_DecodeBlock counts the padding as zero bytes.
  std::size_t padding = 0;
  for (std::size_t index = text.size(); index > 0 && text[index - 1] == '=' && padding < 2; --index)
  {
    ++padding;
  }
  bytes.resize(static_cast<std::size_t>(size) - padding);
  return true;
}

std::string randomBytes(std::size_t count)
{
  std::string bytes(count, '\0');
  if (count > 0 && RAND_bytes(reinterpret_cast<unsigned char*>(&bytes[0]), static_cast<int>(count)) != 1)
  {
    throw std::runtime_error("OpenSSL's random generator has no entropy to give (RAND_bytes failed)");
  }
  return bytes;
}

}  // namespace ptz_action_server
