#pragma once
// spacenavd for tests: a listening AF_UNIX socket on a temporary path, named to libspnav by
// $SPNAV_SOCKET (restored afterwards), that speaks the daemon's side of its protocol as
// libspnav 1.0 expects it (src/proto.h of FreeSpacenav/libspnav): the client's first int is
// a protocol request, REQ_TAG | REQ_CHANGE_PROTO | version, answered with the version granted
// (1); after that every event is eight native ints — UEV_MOTION (0) with x y z rx ry rz and
// the period in ms, UEV_PRESS (1) / UEV_RELEASE (2) with the button number. The handshake is
// answered on a thread of its own, since spnav_open() waits for it on the caller's.
#include "tracking/spacenav_mapping.h"

#include <QByteArray>
#include <QTemporaryDir>

#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <string>
#include <thread>

namespace microsim::testing {

class FakeSpacenavd {
 public:
  static constexpr std::int32_t kReqTag = 0x7faa0000;
  static constexpr std::int32_t kReqChangeProto = 0x5500;

  FakeSpacenavd() : previous_(qgetenv("SPNAV_SOCKET")), hadPrevious_(qEnvironmentVariableIsSet("SPNAV_SOCKET")) {
    path_ = dir_.filePath(QStringLiteral("spnav.sock")).toStdString();
    listener_ = ::socket(AF_UNIX, SOCK_STREAM, 0);
    sockaddr_un addr{};
    addr.sun_family = AF_UNIX;
    std::strncpy(addr.sun_path, path_.c_str(), sizeof addr.sun_path - 1);
    if (::bind(listener_, reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0 || ::listen(listener_, 1) != 0) return;
    qputenv("SPNAV_SOCKET", QByteArray::fromStdString(path_));
    // accept and answer the protocol request as soon as the client connects
    thread_ = std::thread([this] {
      client_ = ::accept(listener_, nullptr, nullptr);
      if (client_ < 0) return;
      if (::read(client_, &request_, sizeof request_) != sizeof request_) return;
      const std::int32_t granted = kReqTag | kReqChangeProto | 1;
      if (::write(client_, &granted, sizeof granted) != sizeof granted) return;
    });
  }
  ~FakeSpacenavd() {
    if (thread_.joinable()) {
      ::shutdown(listener_, SHUT_RDWR);  // an accept() still waiting returns
      thread_.join();
    }
    closeClient();
    if (listener_ >= 0) ::close(listener_);
    if (hadPrevious_)
      qputenv("SPNAV_SOCKET", previous_);
    else
      qunsetenv("SPNAV_SOCKET");
  }
  FakeSpacenavd(const FakeSpacenavd&) = delete;
  FakeSpacenavd& operator=(const FakeSpacenavd&) = delete;

  /// Waits until the client has connected and its protocol request was answered.
  bool handshakeDone() {
    if (thread_.joinable()) thread_.join();
    return client_ >= 0;
  }
  /// The client's first int (the protocol request).
  std::int32_t request() const { return request_; }

  void sendMotion(const tracking::SpacenavMotion& m) {
    send({0, m.x, m.y, m.z, m.rx, m.ry, m.rz, static_cast<std::int32_t>(m.periodMs)});
  }
  void sendButton(int button, bool pressed) { send({pressed ? 1 : 2, button, 0, 0, 0, 0, 0, 0}); }
  /// The daemon goes away.
  void closeClient() {
    if (client_ >= 0) ::close(client_);
    client_ = -1;
  }

 private:
  void send(const std::array<std::int32_t, 8>& packet) {
    if (client_ >= 0) {
      const ssize_t written = ::write(client_, packet.data(), sizeof packet);
      static_cast<void>(written);
    }
  }

  QTemporaryDir dir_;
  std::string path_;
  QByteArray previous_;
  bool hadPrevious_;
  int listener_ = -1;
  int client_ = -1;
  std::int32_t request_ = 0;
  std::thread thread_;
};

}  // namespace microsim::testing
