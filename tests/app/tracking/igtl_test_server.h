#pragma once
// A real OpenIGTLink server for tests: igtl::ServerSocket on a free loopback port, driven
// by a script on its own thread (accept, send library-packed messages or raw bytes, close).
// Messages are packed by the library's own classes, so the client is checked against the
// reference encoder, not against itself.
#include "tracking/igtl_decoder.h"

#include <igtlClientSocket.h>
#include <igtlPositionMessage.h>
#include <igtlSensorMessage.h>
#include <igtlServerSocket.h>
#include <igtlTrackingDataMessage.h>
#include <igtlTransformMessage.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstdint>
#include <functional>
#include <future>
#include <string>
#include <thread>
#include <vector>

namespace microsim::testing {

/// Offset of the CRC-64 in an OpenIGTLink header (version, type, device, timestamp, size).
inline constexpr std::size_t kCrcOffset = 50;

class IgtlTestServer {
 public:
  IgtlTestServer() : server_(igtl::ServerSocket::New()) {
    if (server_->CreateServer(0) == 0) port_ = server_->GetServerPort();
  }
  ~IgtlTestServer() {
    join();
    server_->CloseSocket();
  }
  IgtlTestServer(const IgtlTestServer&) = delete;
  IgtlTestServer& operator=(const IgtlTestServer&) = delete;

  int port() const { return port_; }

  /// Runs `script` on the server thread.
  void run(std::function<void(IgtlTestServer&)> script) {
    thread_ = std::thread([this, script = std::move(script)] { script(*this); });
  }
  void join() {
    if (thread_.joinable()) thread_.join();
  }

  /// Waits for a client (ms); false on timeout.
  bool accept(unsigned long timeoutMs = 20000) {
    client_ = server_->WaitForConnection(timeoutMs);
    return client_.IsNotNull();
  }
  void send(const std::vector<std::uint8_t>& bytes) {
    if (client_.IsNotNull()) client_->Send(bytes.data(), static_cast<int>(bytes.size()));
  }
  void send(igtl::MessageBase* message) {
    message->Pack();
    if (client_.IsNotNull()) client_->Send(message->GetPackPointer(), message->GetPackSize());
  }
  void closeClient() {
    if (client_.IsNotNull()) client_->CloseSocket();
    client_ = nullptr;
  }

 private:
  igtl::ServerSocket::Pointer server_;
  igtl::ClientSocket::Pointer client_;
  std::thread thread_;
  int port_ = 0;
};

/// A pose whose entries are exactly representable in float32 (what OpenIGTLink carries).
inline Eigen::Matrix4d floatPose(double angleRad, const Eigen::Vector3d& axis, const Eigen::Vector3d& position) {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.topLeftCorner<3, 3>() = Eigen::AngleAxisd(angleRad, axis.normalized()).toRotationMatrix();
  m.topRightCorner<3, 1>() = position;
  // entry by entry: in one unity batch gcc 12 compiled Eigen's cast<float>().cast<double>()
  // to no conversion at all (objdump: no cvt in this function), and the tests expecting a
  // float-exact pose failed against the decoder's float-rounded one
  for (double& v : m.reshaped()) {
    const volatile float f = static_cast<float>(v);
    v = static_cast<double>(f);
  }
  return m;
}

/// The source time the decoder reads back from `seconds` (fraction quantised to 2^-32 s).
inline double igtlTime(double seconds) {
  const std::uint64_t ts = tracking::toIgtlTimestamp(seconds);
  return static_cast<double>(ts >> 32) + static_cast<double>(ts & 0xffffffffu) / 4294967296.0;
}

inline void setTime(igtl::MessageBase* message, double seconds) {
  const std::uint64_t ts = tracking::toIgtlTimestamp(seconds);
  message->SetTimeStamp(static_cast<unsigned int>(ts >> 32), static_cast<unsigned int>(ts & 0xffffffffu));
}

inline igtl::TransformMessage::Pointer transformMessage(const std::string& device, const Eigen::Matrix4d& m,
                                                        double seconds) {
  igtl::TransformMessage::Pointer msg = igtl::TransformMessage::New();
  msg->SetDeviceName(device.c_str());
  igtl::Matrix4x4 f;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) f[r][c] = static_cast<float>(m(r, c));
  msg->SetMatrix(f);
  setTime(msg, seconds);
  return msg;
}

inline igtl::PositionMessage::Pointer positionMessage(const std::string& device, const Eigen::Vector3f& p,
                                                      const Eigen::Quaternionf& q, double seconds) {
  igtl::PositionMessage::Pointer msg = igtl::PositionMessage::New();
  msg->SetDeviceName(device.c_str());
  msg->SetPackType(igtl::PositionMessage::ALL);
  msg->SetPosition(p.x(), p.y(), p.z());
  msg->SetQuaternion(q.x(), q.y(), q.z(), q.w());
  setTime(msg, seconds);
  return msg;
}

inline igtl::SensorMessage::Pointer sensorMessage(const std::string& device, double value, double seconds) {
  igtl::SensorMessage::Pointer msg = igtl::SensorMessage::New();
  msg->SetDeviceName(device.c_str());
  msg->SetLength(1);
  msg->SetValue(0, value);
  setTime(msg, seconds);
  return msg;
}

/// Raw bytes of a message with any type and body (the CRC made right unless `breakCrc`).
inline std::vector<std::uint8_t> rawMessage(const char* type, const std::string& device, double seconds,
                                            std::vector<std::uint8_t> body, bool breakCrc = false) {
  std::vector<std::uint8_t> out = tracking::encodeIgtlHeader(type, device, tracking::toIgtlTimestamp(seconds), body);
  if (breakCrc) out[kCrcOffset] ^= 0x5a;
  out.insert(out.end(), body.begin(), body.end());
  return out;
}

/// Bytes of a packed library message (header and body).
inline std::vector<std::uint8_t> packed(igtl::MessageBase* message) {
  message->Pack();
  const auto* p = static_cast<const std::uint8_t*>(message->GetPackPointer());
  return std::vector<std::uint8_t>(p, p + message->GetPackSize());
}

/// A server that sends `poses` to its first client as TRANSFORM messages from "Stylus",
/// 0.01 s apart from 1 s of source time on, then keeps the link up until it is destroyed: for
/// tests in which the client must stop by itself or be killed. (Not from 0: a zero timestamp
/// means "none" in OpenIGTLink, and the client then stamps the pose with its own receive time,
/// which on a loaded machine can fall after the next pose's 0.01 s and reject it.)
class PoseStreamingServer {
 public:
  explicit PoseStreamingServer(std::vector<Eigen::Matrix4d> poses) : poses_(std::move(poses)) {
    server_.run([this, released = release_.get_future().share()](IgtlTestServer& s) {
      if (!s.accept()) return;
      for (std::size_t i = 0; i < poses_.size(); ++i)
        s.send(transformMessage("Stylus", poses_[i], 1.0 + 0.01 * static_cast<double>(i)));
      released.wait();
      s.closeClient();
    });
  }
  ~PoseStreamingServer() { release_.set_value(); }  // before server_ joins its thread
  PoseStreamingServer(const PoseStreamingServer&) = delete;
  PoseStreamingServer& operator=(const PoseStreamingServer&) = delete;

  int port() const { return server_.port(); }
  const std::vector<Eigen::Matrix4d>& poses() const { return poses_; }

 private:
  std::vector<Eigen::Matrix4d> poses_;
  std::promise<void> release_;
  IgtlTestServer server_;
};

}  // namespace microsim::testing
