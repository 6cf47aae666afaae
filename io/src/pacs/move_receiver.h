#pragma once
// Voxray's own C-STORE receiver for C-MOVE: listens on the node's receivePort with the
// calling AE title while one move runs, writing instances into a folder.
#include <atomic>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "voxray/io/pacs.h"

namespace voxray::pacs {

class MoveReceiver {
 public:
  // Starts listening; throws Input when the port cannot be opened.
  MoveReceiver(const PacsNode& node, const std::string& folder, const RetrieveOptions& options);
  ~MoveReceiver();
  // Waits for the association in progress to end, stops listening, returns the files.
  std::vector<std::string> finish();
  // The number of images, from the C-MOVE responses, for progress.
  void setTotal(int total);

  class Scp;

 private:
  std::unique_ptr<Scp> scp_;
  std::thread thread_;
};

}  // namespace voxray::pacs
