#include "ptz_action_server/core/framing/slip.h"

namespace ptz_action_server
{
namespace slip
{
void encode(const std::uint8_t* data, std::size_t size, std::vector<std::uint8_t>& out)
{
  out.push_back(END);  // flushes whatever noise the line put before the frame (RFC 1055's advice)
  for (std::size_t index = 0; index < size; ++index)
  {
    switch (data[index])
    {
      case END:
        out.push_back(ESC);
        out.push_back(ESC_END);
        break;
      case ESC:
        out.push_back(ESC);
        out.push_back(ESC_ESC);
        break;
      default:
        out.push_back(data[index]);
    }
  }
  out.push_back(END);
}

}  // namespace slip
}  // namespace ptz_action_server
