#pragma once
// Instructor passwords, stored only as a salted PBKDF2-HMAC-SHA256 hash (RFC 8018 §5.2):
//   DK = T_1 || T_2 || ...,  T_i = U_1 ^ U_2 ^ ... ^ U_c,
//   U_1 = HMAC(P, S || INT_32_BE(i)),  U_j = HMAC(P, U_{j-1}),
// with a fresh random 16-byte salt per password and a 32-byte key. The iteration count
// c is stored with the hash, so it can be raised later without breaking old hashes.
// Built on QtCore's QMessageAuthenticationCode (assessment does not link QtNetwork).

#include <QByteArray>
#include <QString>

namespace microsim::assessment {

struct PasswordHash {
  QString algorithm;  ///< "pbkdf2-sha256"
  int iterations = 0;
  QByteArray salt;
  QByteArray hash;
};

/// PBKDF2 with HMAC-SHA256 as the PRF; `keyLength` bytes of derived key.
QByteArray pbkdf2HmacSha256(const QByteArray& password, const QByteArray& salt, int iterations,
                            int keyLength);

/// A new hash of `password` (UTF-8) with a random salt.
PasswordHash hashPassword(const QString& password, int iterations);

/// True when `password` matches; the hashes are compared in constant time.
bool verifyPassword(const QString& password, const PasswordHash& stored);

/// a == b, in time that depends on the lengths only.
bool constantTimeEquals(const QByteArray& a, const QByteArray& b);

}  // namespace microsim::assessment
