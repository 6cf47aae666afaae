#pragma once
// A real Orthanc (Debian's orthanc + orthanc-dicomweb), started by a test on loopback with its
// own configuration, free ports chosen now and a temporary storage folder under the build
// tree; stopped (and its folder removed) when the object goes. Never the system service.
#include <string>
#include <vector>

#include "voxray/io/pacs.h"

namespace voxray::test {

class OrthancServer {
 public:
  static constexpr const char* kAe = "ORTHANC";
  static constexpr const char* kUser = "voxray";
  static constexpr const char* kPassword = "test-secret";

  // Throws std::runtime_error with the reason (and Orthanc's log) when it does not start.
  OrthancServer();
  ~OrthancServer();
  OrthancServer(const OrthancServer&) = delete;
  OrthancServer& operator=(const OrthancServer&) = delete;

  // Uploads every DICOM file under PATH (a file or folder) through POST /instances;
  // returns the count. Throws when Orthanc refuses one.
  int upload(const std::string& path);
  // GET on the REST API (with the test user); returns the body, throws on HTTP >= 400.
  std::string get(const std::string& path) const;
  // Stops the server now (for "server went away" tests); SIGKILL: it dies mid-transfer.
  void stop(int signal = 15 /* SIGTERM */);
  // Freezes the server (SIGSTOP: its sockets stay open, it sends nothing) and thaws it.
  void freeze();
  void thaw();

  int httpPort = 0, dicomPort = 0, movePort = 0;
  std::string folder;  // storage, configuration and log
  std::string log() const;

  // Nodes pointing at this server: DIMSE with C-GET, DIMSE with C-MOVE into movePort, and
  // DICOMweb with basic authentication.
  PacsNode dimseNode() const;
  PacsNode moveNode() const;
  PacsNode webNode() const;

 private:
  int pid_ = -1;
};

// A TCP port on 127.0.0.1 that is free now.
int freePort();
// A socket bound to a free port on 127.0.0.1 (PORT), listening when LISTENING: a node that
// takes connections and never answers. Throws when there is none; the caller closes it.
int loopbackSocket(int& port, bool listening);
// A fresh folder under the build tree's test area.
std::string tempFolder(const std::string& tag);

}  // namespace voxray::test
