/**
 * \file
 * \brief WS-Security for ONVIF (protocols.md section 7): UsernameToken PasswordDigest, and the xsd:dateTime its
 * Created is written in.
 */
#include <cmath>
#include <ctime>

#include "ptz_action_server/core/http/crypto.h"
#include "ptz_action_server/core/onvif/onvif_codec.h"
#include "ptz_action_server/core/parse_number.h"
#include "ptz_action_server/core/text.h"

namespace ptz_action_server
{
namespace onvif
{
UsernameToken newUsernameToken(const std::string& username, const std::string& created)
{
  UsernameToken token;
  token.username = username;
  token.nonce = randomBytes(16);
  token.created = created;
  return token;
}

std::string passwordDigest(const std::string& nonce, const std::string& created, const std::string& password)
{
  return base64Encode(sha1(nonce + created + password));
}

std::string isoTime(double utc_seconds)
{
  const std::time_t whole = static_cast<std::time_t>(std::floor(utc_seconds));
  const int millis = std::min(999, static_cast<int>((utc_seconds - static_cast<double>(whole)) * 1000.0));
  std::tm parts{};
  gmtime_r(&whole, &parts);
  return formatText("%04d-%02d-%02dT%02d:%02d:%02d.%03dZ", parts.tm_year + 1900, parts.tm_mon + 1, parts.tm_mday,
                    parts.tm_hour, parts.tm_min, parts.tm_sec, millis);
}

namespace
{
bool leapYear(long year)
{
  return (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
}

/// Reads exactly \p digits decimal digits at \p at into \p value; false if there are not that many.
bool fixedDigits(const std::string& text, std::size_t& at, int digits, int& value)
{
  value = 0;
  for (int index = 0; index < digits; ++index, ++at)
  {
    if (at >= text.size() || text[at] < '0' || text[at] > '9')
    {
      return false;
    }
    value = value * 10 + (text[at] - '0');
  }
  return true;
}

bool expect(const std::string& text, std::size_t& at, char wanted)
{
  if (at >= text.size() || text[at] != wanted)
  {
    return false;
  }
  ++at;
  return true;
}
}  // namespace

bool parseIsoTime(const std::string& text, double& utc_seconds)
{
  // xsd:dateTime: '-'? yyyy '-' mm '-' dd 'T' hh ':' mm ':' ss ('.' s+)? (('+' | '-') hh ':' mm | 'Z')?
  std::size_t at = 0;
  const bool before_zero = !text.empty() && text[0] == '-';
  at += before_zero ? 1 : 0;
  const std::size_t year_begins = at;
  long year = 0;
  while (at < text.size() && text[at] >= '0' && text[at] <= '9' && at - year_begins < 9)
  {
    year = year * 10 + (text[at++] - '0');
  }
  const std::size_t year_digits = at - year_begins;
  if (year_digits < 4 || (year_digits > 4 && text[year_begins] == '0') || (before_zero && year == 0))
  {
    return false;  // four digits at least, no leading zero beyond them, no year -0000
  }
  year = before_zero ? -year : year;
  int month = 0, day = 0, hour = 0, minute = 0, second = 0;
  if (!expect(text, at, '-') || !fixedDigits(text, at, 2, month) || !expect(text, at, '-') ||
      !fixedDigits(text, at, 2, day) || !expect(text, at, 'T') || !fixedDigits(text, at, 2, hour) ||
      !expect(text, at, ':') || !fixedDigits(text, at, 2, minute) || !expect(text, at, ':') ||
      !fixedDigits(text, at, 2, second))
  {
    return false;
  }
  double fraction = 0.0;
  if (at < text.size() && text[at] == '.')
  {
    const std::size_t end = text.find_first_not_of("0123456789", at + 1);
    const std::size_t digits_end = end == std::string::npos ? text.size() : end;
    if (digits_end == at + 1 || !parseNumber("0" + text.substr(at, digits_end - at), fraction))
    {
      return false;
    }
    at = digits_end;
  }
  int offset_minutes = 0;  // a time without a zone is taken as UTC (WS-Security stamps UTC)
  if (at < text.size() && text[at] == 'Z')
  {
    ++at;
  }
  else if (at < text.size() && (text[at] == '+' || text[at] == '-'))
  {
    const int sign = text[at++] == '-' ? -1 : 1;
    int zone_hours = 0, zone_minutes = 0;
    if (!fixedDigits(text, at, 2, zone_hours) || !expect(text, at, ':') || !fixedDigits(text, at, 2, zone_minutes) ||
        zone_minutes > 59 || zone_hours > 14 || (zone_hours == 14 && zone_minutes != 0))
    {
      return false;
    }
    offset_minutes = sign * (zone_hours * 60 + zone_minutes);
  }
  static constexpr int DAYS[12] = { 31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31 };
  const bool end_of_day = hour == 24 && minute == 0 && second == 0 && fraction == 0.0;  // 24:00:00 is the next 00:00
  if (at != text.size() || month < 1 || month > 12 || day < 1 ||
      day > DAYS[month - 1] + (month == 2 && leapYear(year) ? 1 : 0) || (hour > 23 && !end_of_day) || minute > 59 ||
      second > 60)
  {
    return false;
  }
  std::tm parts{};
  parts.tm_year = static_cast<int>(year - 1900);
  parts.tm_mon = month - 1;
  parts.tm_mday = day;
  parts.tm_hour = hour;
  parts.tm_min = minute;
  parts.tm_sec = second;
  utc_seconds = static_cast<double>(timegm(&parts)) + fraction - 60.0 * offset_minutes;
  return true;
}

}  // namespace onvif
}  // namespace ptz_action_server
