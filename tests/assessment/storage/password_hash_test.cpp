#include "microsim/assessment/storage/password_hash.h"

#include <gtest/gtest.h>

namespace microsim::assessment {
namespace {

// RFC 7914 §11, the PBKDF2-HMAC-SHA256 test vectors
TEST(PasswordHash, Rfc7914Vectors) {
  EXPECT_EQ(pbkdf2HmacSha256("passwd", "salt", 1, 64).toHex().toStdString(),
            "55ac046e56e3089fec1691c22544b605f94185216dde0465e68b9d57c20dacbc"
            "49ca9cccf179b645991664b39d77ef317c71b845b1e30bd509112041d3a19783");
  EXPECT_EQ(pbkdf2HmacSha256("Password", "NaCl", 80000, 64).toHex().toStdString(),
            "4ddcd8f60b98be21830cee5ef22701f9641a4418d04c0414aeff08876b34ab56"
            "a1d425a1225833549adb841b51c9b3176a272bdebba1d078478f62b397f33c8d");
}

// a key shorter than one block, and one that needs a second block
TEST(PasswordHash, KeyLengthsAcrossBlocks) {
  const QByteArray full = pbkdf2HmacSha256("password", "salt", 2, 64);
  EXPECT_EQ(full.size(), 64);
  EXPECT_EQ(pbkdf2HmacSha256("password", "salt", 2, 20), full.left(20));
  EXPECT_EQ(full.left(32).toHex().toStdString(),
            "ae4d0c95af6b46d32d0adff928f06dd02a303f8ef3c251dfd6e2d85a95474c43");
}

TEST(PasswordHash, SaltedHashesVerify) {
  const PasswordHash a = hashPassword(QStringLiteral("sütur€ 42"), 100);
  const PasswordHash b = hashPassword(QStringLiteral("sütur€ 42"), 100);
  EXPECT_EQ(a.algorithm.toStdString(), "pbkdf2-sha256");
  EXPECT_EQ(a.iterations, 100);
  EXPECT_NE(a.salt, b.salt);
  EXPECT_NE(a.hash, b.hash);
  EXPECT_TRUE(verifyPassword(QStringLiteral("sütur€ 42"), a));
  EXPECT_FALSE(verifyPassword(QStringLiteral("sutur€ 42"), a));
  PasswordHash fewer = a;
  fewer.iterations = 99;
  EXPECT_FALSE(verifyPassword(QStringLiteral("sütur€ 42"), fewer));
}

TEST(PasswordHash, ConstantTimeEquals) {
  EXPECT_TRUE(constantTimeEquals("abc", "abc"));
  EXPECT_FALSE(constantTimeEquals("abc", "abd"));
  EXPECT_FALSE(constantTimeEquals("abc", "abcd"));
  EXPECT_TRUE(constantTimeEquals({}, {}));
}

}  // namespace
}  // namespace microsim::assessment
