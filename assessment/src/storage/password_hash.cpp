#include "microsim/assessment/storage/password_hash.h"

#include <QMessageAuthenticationCode>
#include <QRandomGenerator>

namespace microsim::assessment {

namespace {

constexpr int kSaltBytes = 16;
constexpr int kKeyBytes = 32;

}  // namespace

QByteArray pbkdf2HmacSha256(const QByteArray& password, const QByteArray& salt, int iterations,
                            int keyLength) {
  QByteArray key;
  if (iterations < 1 || keyLength < 1) return key;
  QMessageAuthenticationCode mac(QCryptographicHash::Sha256, password);
  for (quint32 block = 1; key.size() < keyLength; ++block) {
    // U_1 = HMAC(P, S || INT_32_BE(block))
    const char index[4] = {char(block >> 24), char(block >> 16), char(block >> 8), char(block)};
    mac.reset();
    mac.addData(salt);
    mac.addData(index, 4);
    QByteArray u = mac.result();
    QByteArray t = u;
    // T = U_1 ^ ... ^ U_c
    for (int j = 1; j < iterations; ++j) {
      mac.reset();
      mac.addData(u);
      u = mac.result();
      for (qsizetype b = 0; b < t.size(); ++b) t[b] = char(t[b] ^ u[b]);
    }
    key += t;
  }
  key.truncate(keyLength);
  return key;
}

PasswordHash hashPassword(const QString& password, int iterations) {
  PasswordHash h;
  h.algorithm = QStringLiteral("pbkdf2-sha256");
  h.iterations = iterations;
  h.salt.resize(kSaltBytes);
  QRandomGenerator::system()->fillRange(reinterpret_cast<quint32*>(h.salt.data()), kSaltBytes / 4);
  h.hash = pbkdf2HmacSha256(password.toUtf8(), h.salt, iterations, kKeyBytes);
  return h;
}

bool verifyPassword(const QString& password, const PasswordHash& stored) {
  if (stored.algorithm != QLatin1String("pbkdf2-sha256") || stored.iterations < 1 ||
      stored.hash.isEmpty())
    return false;
  const QByteArray candidate =
      pbkdf2HmacSha256(password.toUtf8(), stored.salt, stored.iterations, int(stored.hash.size()));
  return constantTimeEquals(candidate, stored.hash);
}

bool constantTimeEquals(const QByteArray& a, const QByteArray& b) {
  if (a.size() != b.size()) return false;
  unsigned char diff = 0;
  for (qsizetype i = 0; i < a.size(); ++i)
    diff |= static_cast<unsigned char>(a[i] ^ b[i]);
  return diff == 0;
}

}  // namespace microsim::assessment
