#pragma once
// The one error type of Voxray. Every layer throws voxray::Error with a message a
// user can act on: what is wrong, with which file or device, and what to do.
#include <stdexcept>
#include <string>

namespace voxray {

class Error : public std::runtime_error {
 public:
  enum class Kind {
    Input,      // a file or argument is wrong (bad size, missing slice, broken DICOM)
    Device,     // OpenCL: no platform, build failure, out of device memory
    Output,     // cannot write an image
    Cancelled,  // the user asked to stop (LoadOptions::cancel): show nothing, or "Cancelled"
    Internal    // a bug: should never reach the user
  };
  Error(Kind kind, const std::string& message) : std::runtime_error(message), kind_(kind) {}
  Kind kind() const { return kind_; }

 private:
  Kind kind_;
};

inline Error inputError(const std::string& m) { return Error(Error::Kind::Input, m); }
inline Error deviceError(const std::string& m) { return Error(Error::Kind::Device, m); }
inline Error outputError(const std::string& m) { return Error(Error::Kind::Output, m); }
inline Error cancelledError(const std::string& m) { return Error(Error::Kind::Cancelled, m); }

// A cancellation is not a failure: callers show nothing (or "Cancelled"), not an error box.
inline bool isCancellation(const std::exception& e) {
  const auto* error = dynamic_cast<const Error*>(&e);
  return error && error->kind() == Error::Kind::Cancelled;
}

}  // namespace voxray
