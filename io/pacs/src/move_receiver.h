#pragma once
// Voxray's own C-STORE receiver for C-MOVE: listens on the node's receivePort with the
// calling AE title while one move runs, writing instances into a folder.
#include <atomic>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "cancellable_transport.h"
#include "voxray/io/pacs.h"

namespace voxray::pacs {

class MoveReceiver {
 public:
  // Starts listening; throws Input when the port cannot be opened. Every byte that arrives
  // touches IDLE (the C-MOVE's own association waits on it too).
  MoveReceiver(const PacsNode& node, const std::string& folder, const RetrieveOptions& options,
               IdleDeadline* idle);
  ~MoveReceiver();
  // Waits for the association in progress to end (at most the node's timeout after its last
  // byte), stops listening, returns the files.
  std::vector<std::string> finish();
  // The number of images, from the C-MOVE responses, for progress.
  void setTotal(int total);

  class Scp;

 private:
  std::unique_ptr<Scp> scp_;
  std::thread thread_;
};

}  // namespace voxray::pacs
