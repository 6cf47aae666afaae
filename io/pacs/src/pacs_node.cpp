// PACS node addresses and the node configuration file.
#include <cstdlib>
#include <fstream>

#include <nlohmann/json.hpp>

#include "pacs_messages.h"
#include "voxray/io/error.h"
#include "voxray/io/pacs.h"

namespace voxray {
namespace {

const char* kAddressHelp =
    "; give dicom://CALLED_AE@host:port (DIMSE) or http(s)://host/path (DICOMweb)";

bool startsWith(const std::string& s, const std::string& prefix) {
  return s.compare(0, prefix.size(), prefix) == 0;
}

int parsePort(const std::string& text, const std::string& address) {
  char* end = nullptr;
  long port = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || port < 1 || port > 65535)
    throw inputError("PACS address " + address + ": port '" + text + "' is not 1..65535" +
                     kAddressHelp);
  return int(port);
}

}  // namespace

std::string PacsNode::label() const {
  if (transport == Transport::Web) return pacs::redactUrl(baseUrl);
  return calledAe + "@" + host + ":" + std::to_string(port);
}

PacsNode parsePacsNode(const std::string& address) {
  PacsNode node;
  node.name = address;
  if (startsWith(address, "http://") || startsWith(address, "https://")) {
    node.transport = PacsNode::Transport::Web;
    node.baseUrl = address;
    while (!node.baseUrl.empty() && node.baseUrl.back() == '/') node.baseUrl.pop_back();
    if (node.baseUrl.find('@') != std::string::npos)
      throw inputError("PACS address: put the user and password in the node configuration (" +
                       pacsConfigPath() + "), not in the URL");
    return node;
  }
  if (!startsWith(address, "dicom://"))
    // Redacted: an address of another scheme may still hold a password or a token.
    throw inputError("PACS address '" + pacs::redactUrl(address) +
                     "' is not a node name or address" + kAddressHelp);
  std::string rest = address.substr(8);
  size_t at = rest.find('@'), colon = rest.rfind(':');
  if (at == std::string::npos || at == 0 || colon == std::string::npos || colon < at)
    throw inputError("PACS address " + address + " lacks the AE title or port" + kAddressHelp);
  node.calledAe = rest.substr(0, at);
  node.host = rest.substr(at + 1, colon - at - 1);
  node.port = parsePort(rest.substr(colon + 1), address);
  if (node.calledAe.size() > 16 || node.host.empty())
    throw inputError("PACS address " + address +
                     ": the AE title must be 1..16 characters and the host not empty");
  return node;
}

std::string pacsConfigPath() {
  const char* xdg = std::getenv("XDG_CONFIG_HOME");
  if (xdg && *xdg) return std::string(xdg) + "/voxray/pacs-nodes.json";
  const char* home = std::getenv("HOME");
  return std::string(home ? home : ".") + "/.config/voxray/pacs-nodes.json";
}

std::vector<PacsNode> loadPacsNodes(const std::string& path) {
  std::ifstream in(path);
  if (!in) return {};
  std::vector<PacsNode> nodes;
  try {
    auto json = nlohmann::json::parse(in);
    for (const auto& [name, entry] : json.at("nodes").items()) {
      PacsNode node = parsePacsNode(entry.at("url").get<std::string>());
      node.name = name;
      node.callingAe = entry.value("callingAe", node.callingAe);
      node.receivePort = entry.value("receivePort", 0);
      node.user = entry.value("user", "");
      node.password = entry.value("password", "");
      node.bearerToken = entry.value("bearerToken", "");
      node.caFile = entry.value("caFile", "");
      node.timeoutSec = entry.value("timeout", node.timeoutSec);
      nodes.push_back(node);
    }
  } catch (const nlohmann::json::exception& e) {
    throw inputError("PACS configuration " + path + " is not valid (" + e.what() +
                     "); see the README's PACS section for its form");
  }
  return nodes;
}

PacsNode resolvePacsNode(const std::string& nameOrAddress, const std::string& configPath) {
  for (const auto& node : loadPacsNodes(configPath))
    if (node.name == nameOrAddress) return node;
  if (nameOrAddress.find("://") == std::string::npos)
    throw inputError("PACS node '" + nameOrAddress + "' is not configured in " + configPath +
                     kAddressHelp);
  return parsePacsNode(nameOrAddress);
}

}  // namespace voxray
