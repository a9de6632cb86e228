#include "ptz_action_server/core/onvif/onvif_xml.h"

#include <algorithm>
#include <cstring>

#include "ptz_action_server/core/text.h"

namespace ptz_action_server
{
namespace onvif
{
std::string localName(const Element& element)
{
  const char* name = element.Name();
  const char* colon = std::strchr(name, ':');
  return colon == nullptr ? name : colon + 1;
}

std::string namespaceOf(const Element& element)
{
  const char* name = element.Name();
  const char* colon = std::strchr(name, ':');
  const std::string declaration = colon == nullptr ? "xmlns" : "xmlns:" + std::string(name, colon);
  for (const tinyxml2::XMLNode* node = &element; node != nullptr; node = node->Parent())
  {
    const Element* scope = node->ToElement();
    if (scope == nullptr)
    {
      break;
    }
    if (const char* uri = scope->Attribute(declaration.c_str()))
    {
      return uri;
    }
  }
  return {};
}

bool is(const Element& element, const char* uri, const char* local)
{
  return localName(element) == local && namespaceOf(element) == uri;
}

const Element* child(const Element* parent, const char* uri, const char* local)
{
  for (const Element* item = parent == nullptr ? nullptr : parent->FirstChildElement(); item != nullptr;
       item = item->NextSiblingElement())
  {
    if (is(*item, uri, local))
    {
      return item;
    }
  }
  return nullptr;
}

std::vector<const Element*> children(const Element* parent, const char* uri, const char* local)
{
  std::vector<const Element*> found;
  for (const Element* item = parent == nullptr ? nullptr : parent->FirstChildElement(); item != nullptr;
       item = item->NextSiblingElement())
  {
    if (is(*item, uri, local))
    {
      found.push_back(item);
    }
  }
  return found;
}

const Element* path(const Element* parent, const char* uri, std::initializer_list<const char*> locals)
{
  const Element* at = parent;
  for (const char* local : locals)
  {
    at = child(at, uri, local);
  }
  return at;
}

const char* attribute(const Element* element, const char* local)
{
  if (element == nullptr)
  {
    return nullptr;
  }
  for (const tinyxml2::XMLAttribute* item = element->FirstAttribute(); item != nullptr; item = item->Next())
  {
    const char* name = item->Name();
    const char* colon = std::strchr(name, ':');
    if (std::strcmp(colon == nullptr ? name : colon + 1, local) == 0 && std::strncmp(name, "xmlns", 5) != 0)
    {
      return item->Value();
    }
  }
  return nullptr;
}

std::string text(const Element* element)
{
  const char* value = element == nullptr ? nullptr : element->GetText();
  if (value == nullptr)
  {
    return {};
  }
  return trimmed(value);
}

std::string parseSoap(const std::string& xml, SoapMessage& message)
{
  message.header = nullptr;
  message.content = nullptr;
  message.fault = false;
  message.fault_code.clear();
  message.subcodes.clear();
  message.fault_text.clear();
  if (message.document.Parse(xml.data(), xml.size()) != tinyxml2::XML_SUCCESS)
  {
    return std::string("not XML: ") + message.document.ErrorName();
  }
  const Element* envelope = message.document.RootElement();
  if (envelope == nullptr || !is(*envelope, ns::SOAP, "Envelope"))
  {
    return "no SOAP 1.2 Envelope";
  }
  message.header = child(envelope, ns::SOAP, "Header");
  const Element* body = child(envelope, ns::SOAP, "Body");
  if (body == nullptr)
  {
    return "no SOAP Body";
  }
  message.content = body->FirstChildElement();
  if (message.content == nullptr)
  {
    return "an empty SOAP Body";
  }
  if (is(*message.content, ns::SOAP, "Fault"))
  {
    message.fault = true;
    const Element* code = child(message.content, ns::SOAP, "Code");
    message.fault_code = text(child(code, ns::SOAP, "Value"));
    std::string names;
    // ONVIF nests its faults two deep (env:Sender / ter:InvalidArgVal / ter:NoProfile); a few levels are plenty.
    for (const Element* subcode = child(code, ns::SOAP, "Subcode"); subcode != nullptr && message.subcodes.size() < 8;
         subcode = child(subcode, ns::SOAP, "Subcode"))
    {
      const std::string value = text(child(subcode, ns::SOAP, "Value"));
      if (!value.empty())
      {
        message.subcodes.push_back(value);
        names += (names.empty() ? "" : "/") + value;
      }
    }
    if (names.empty())
    {
      names = message.fault_code.empty() ? "SOAP fault" : message.fault_code;
    }
    const std::string reason = text(path(message.content, ns::SOAP, { "Reason", "Text" }));
    message.fault_text = names + (reason.empty() ? "" : ": " + reason);
  }
  return {};
}

bool faultHas(const SoapMessage& message, const char* local)
{
  if (!message.fault)
  {
    return false;
  }
  auto matches = [local](const std::string& qname) {
    const std::size_t colon = qname.find(':');
    return qname.compare(colon == std::string::npos ? 0 : colon + 1, std::string::npos, local) == 0;
  };
  return matches(message.fault_code) || std::any_of(message.subcodes.begin(), message.subcodes.end(), matches);
}

std::string escaped(const std::string& text)
{
  std::string out;
  out.reserve(text.size());
  for (char c : text)
  {
    switch (c)
    {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

}  // namespace onvif
}  // namespace ptz_action_server
