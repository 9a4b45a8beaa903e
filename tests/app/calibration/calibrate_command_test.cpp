// `microsim-cli calibrate pivot|register` on input files, as a user runs it.
#include "support/cli_runner.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

#include <Eigen/Geometry>

#include <gtest/gtest.h>

namespace {

using microsim::testing::runCli;

QJsonObject runCalibrate(const QString& kind, const QJsonObject& input, int expectedExit) {
  QTemporaryDir dir;
  const QString in = dir.filePath(QStringLiteral("in.json"));
  const QString out = dir.filePath(QStringLiteral("out.json"));
  QFile f(in);
  EXPECT_TRUE(f.open(QIODevice::WriteOnly));
  f.write(QJsonDocument(input).toJson());
  f.close();
  const microsim::testing::CliRun r =
      runCli({QStringLiteral("calibrate"), kind, QStringLiteral("--input"), in, QStringLiteral("--json"), out});
  EXPECT_EQ(r.exitCode, expectedExit) << r.err.toStdString();
  QFile o(out);
  EXPECT_TRUE(o.open(QIODevice::ReadOnly));
  return QJsonDocument::fromJson(o.readAll()).object();
}

QJsonArray vec(const Eigen::Vector3d& v) { return QJsonArray{v.x(), v.y(), v.z()}; }

TEST(CalibrateCommand, PivotFindsTheTip) {
  const Eigen::Vector3d tip(1.0, 2.0, 130.0), pivot(10.0, 20.0, 30.0);
  QJsonArray poses;
  for (int i = 0; i < 12; ++i) {
    const Eigen::Matrix3d r = (Eigen::AngleAxisd(0.1 * i - 0.6, Eigen::Vector3d::UnitX()) *
                               Eigen::AngleAxisd(0.5 * std::sin(i), Eigen::Vector3d::UnitY()) *
                               Eigen::AngleAxisd(0.7 * i, Eigen::Vector3d::UnitZ()))
                                  .toRotationMatrix();
    Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
    m.topLeftCorner<3, 3>() = r;
    m.topRightCorner<3, 1>() = pivot - r * tip;
    QJsonArray a;
    for (int k = 0; k < 16; ++k) a.append(m(k / 4, k % 4));
    poses.append(a);
  }
  const QJsonObject result = runCalibrate(QStringLiteral("pivot"), QJsonObject{{QStringLiteral("poses"), poses}}, 0);
  EXPECT_EQ(result.value(QStringLiteral("status")).toString().toStdString(), "ok");
  const QJsonArray t = result.value(QStringLiteral("tip_offset")).toArray();
  ASSERT_EQ(t.size(), 3);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(t.at(i).toDouble(), tip(i), 1e-6);
  EXPECT_LT(result.value(QStringLiteral("rms_mm")).toDouble(), 1e-6);
  EXPECT_EQ(result.value(QStringLiteral("poses")).toInt(), 12);

  // too few poses: status says so, exit code 1, JSON still written
  const QJsonObject few = runCalibrate(QStringLiteral("pivot"),
                                       QJsonObject{{QStringLiteral("poses"), QJsonArray{poses.at(0), poses.at(1)}}}, 1);
  EXPECT_EQ(few.value(QStringLiteral("status")).toString().toStdString(), "too_few_poses");
}

TEST(CalibrateCommand, RegisterFindsTheTransformAndReportsFreAndTre) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = Eigen::AngleAxisd(1.2, Eigen::Vector3d(0, 0, 1)).toRotationMatrix();
  t.translation() = Eigen::Vector3d(5, -6, 7);
  const std::vector<Eigen::Vector3d> fiducials{{0, 0, 0}, {40, 0, 0}, {0, 40, 0}, {0, 0, 40}};
  QJsonArray fid, check;
  for (const Eigen::Vector3d& p : fiducials)
    fid.append(QJsonObject{{QStringLiteral("tracker"), vec(p)}, {QStringLiteral("scene"), vec(t * p)}});
  check.append(QJsonObject{{QStringLiteral("tracker"), vec({10, 10, 10})}, {QStringLiteral("scene"), vec(t * Eigen::Vector3d(10, 10, 10))}});
  const QJsonObject result = runCalibrate(
      QStringLiteral("register"), QJsonObject{{QStringLiteral("fiducials"), fid}, {QStringLiteral("check_points"), check}}, 0);
  EXPECT_EQ(result.value(QStringLiteral("status")).toString().toStdString(), "ok");
  const QJsonArray m = result.value(QStringLiteral("matrix")).toArray();
  ASSERT_EQ(m.size(), 16);
  for (int k = 0; k < 16; ++k) EXPECT_NEAR(m.at(k).toDouble(), t.matrix()(k / 4, k % 4), 1e-9) << k;
  EXPECT_LT(result.value(QStringLiteral("fre_rms_mm")).toDouble(), 1e-9);
  EXPECT_LT(result.value(QStringLiteral("tre_rms_mm")).toDouble(), 1e-9);
  EXPECT_EQ(result.value(QStringLiteral("check_points")).toInt(), 1);
}

TEST(CalibrateCommand, UsageErrors) {
  EXPECT_EQ(runCli({QStringLiteral("calibrate"), QStringLiteral("wobble"), QStringLiteral("--input"), QStringLiteral("x")}).exitCode, 2);
  EXPECT_EQ(runCli({QStringLiteral("calibrate"), QStringLiteral("pivot")}).exitCode, 2);
  EXPECT_EQ(runCli({QStringLiteral("calibrate"), QStringLiteral("pivot"), QStringLiteral("--input"),
                    QStringLiteral("/nonexistent/in.json")}).exitCode, 1);
}

}  // namespace
