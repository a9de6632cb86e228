/**
 * \file
 * \brief SOAP 1.2 for ONVIF on tinyxml2, by namespace URI and local name: a prefix is whatever the sender declared,
 * never assumed (`s:`, `env:`, `SOAP-ENV:` or a default namespace all read the same).
 */
#pragma once

#include <string>
#include <vector>

#include <tinyxml2.h>

namespace ptz_action_server
{
namespace onvif
{
/// The namespaces of protocols.md section 7.
namespace ns
{
constexpr const char* SOAP = "http://www.w3.org/2003/05/soap-envelope";
constexpr const char* DEVICE = "http://www.onvif.org/ver10/device/wsdl";
constexpr const char* MEDIA = "http://www.onvif.org/ver10/media/wsdl";
constexpr const char* PTZ = "http://www.onvif.org/ver20/ptz/wsdl";
constexpr const char* IMAGING = "http://www.onvif.org/ver20/imaging/wsdl";  ///< focus and iris (timg)
constexpr const char* SCHEMA = "http://www.onvif.org/ver10/schema";
constexpr const char* WSSE = "http://docs.oasis-open.org/wss/2004/01/oasis-200401-wss-wssecurity-secext-1.0.xsd";
constexpr const char* WSU = "http://docs.oasis-open.org/wss/2004/01/oasis-200401-wss-wssecurity-utility-1.0.xsd";
}  // namespace ns

using Element = tinyxml2::XMLElement;

/// The local part of the element's name ("AbsoluteMove" of "tptz:AbsoluteMove").
std::string localName(const Element& element);
/// The namespace URI the element's prefix (or the default namespace) is bound to where it stands; "" if unbound.
std::string namespaceOf(const Element& element);
/// True if \p element is {\p uri}\p local.
bool is(const Element& element, const char* uri, const char* local);
/// The first child {\p uri}\p local of \p parent, or nullptr (also for a null parent).
const Element* child(const Element* parent, const char* uri, const char* local);
/// Every such child.
std::vector<const Element*> children(const Element* parent, const char* uri, const char* local);
/// Follows a path of children in one namespace: child(child(parent, uri, a), uri, b)...
const Element* path(const Element* parent, const char* uri, std::initializer_list<const char*> locals);
/// The attribute whose local name is \p local (unqualified, as ONVIF's x, y, space, token), or nullptr.
const char* attribute(const Element* element, const char* local);
/// The element's text, trimmed ("" for none).
std::string text(const Element* element);

/// A SOAP envelope, read.
struct SoapMessage
{
  tinyxml2::XMLDocument document;
  const Element* header = nullptr;   ///< s:Header, if any
  const Element* content = nullptr;  ///< the first element in s:Body (the response, or s:Fault)
  bool fault = false;
  std::string fault_code;             ///< Code/Value: "env:Sender", "env:Receiver" (as the sender prefixed it)
  std::vector<std::string> subcodes;  ///< Subcode/Value, then Subcode/Subcode/Value...: "ter:InvalidArgVal", ...
  /// "ter:InvalidArgVal/ter:NoProfile: The requested profile token does not exist" (the subcodes, else the code; then
  /// the reason)
  std::string fault_text;
};

/// True if \p message is a fault with a (sub)code whose local part is \p local ("ActionNotSupported" matches
/// "ter:ActionNotSupported" whatever the prefix).
bool faultHas(const SoapMessage& message, const char* local);

/// Reads \p xml as a SOAP 1.2 envelope; "" or what is wrong ("not XML: ...", "no s:Envelope", "an empty s:Body").
std::string parseSoap(const std::string& xml, SoapMessage& message);

/// \p text with &, <, >, " escaped for XML text and attributes.
std::string escaped(const std::string& text);

}  // namespace onvif
}  // namespace ptz_action_server
