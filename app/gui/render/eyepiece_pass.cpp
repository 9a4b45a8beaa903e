#include "gui/render/eyepiece_pass.h"

#include "gui/render/shader_program.h"

#include <QOpenGLExtraFunctions>
#include <QOpenGLFramebufferObject>
#include <QOpenGLShaderProgram>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace microsim::gui {

namespace {

// the field stop's soft edge, and the widest blur, as fractions of the area's size
constexpr float kFieldEdgeFraction = 0.06f;
constexpr float kMaxBlurFraction = 0.006f;

std::unique_ptr<QOpenGLFramebufferObject> pictureTarget(const QSize& size, int samples) {
  QOpenGLFramebufferObjectFormat format;
  format.setAttachment(QOpenGLFramebufferObject::Depth);
  format.setSamples(samples);
  format.setInternalTextureFormat(GL_RGBA8);
  return std::make_unique<QOpenGLFramebufferObject>(size, format);
}

}  // namespace

EyepieceField eyepieceField(const QRect& area) {
  const float radius = 0.5f * static_cast<float>(std::min(area.width(), area.height()));
  return {QPointF(area.x() + 0.5 * area.width(), area.y() + 0.5 * area.height()), radius, kFieldEdgeFraction * 2.0f * radius};
}

std::vector<float> fieldMaskTriangles(const QRect& area, int segments) {
  const EyepieceField field = eyepieceField(area);
  const float halfWidth = 0.5f * static_cast<float>(std::max(1, area.width()));
  const float halfHeight = 0.5f * static_cast<float>(std::max(1, area.height()));
  const float outer = 2.0f * std::max(halfWidth, halfHeight);  // past every corner
  std::vector<float> out;
  out.reserve(static_cast<std::size_t>(segments) * 12);
  const auto at = [&](int i, float radius) {
    const double angle = 2.0 * std::numbers::pi * i / segments;
    return QPointF(radius * std::cos(angle) / halfWidth, radius * std::sin(angle) / halfHeight);
  };
  for (int i = 0; i < segments; ++i) {
    const QPointF a = at(i, field.radius), b = at(i + 1, field.radius), c = at(i, outer), d = at(i + 1, outer);
    for (const QPointF& p : {a, c, d, a, d, b}) {
      out.push_back(static_cast<float>(p.x()));
      out.push_back(static_cast<float>(p.y()));
    }
  }
  return out;
}

float maxBlurPixels(int height) { return std::max(1.5f, kMaxBlurFraction * static_cast<float>(height)); }

EyepiecePass::EyepiecePass() = default;
EyepiecePass::~EyepiecePass() = default;

bool EyepiecePass::create(bool softwareRenderer, QString* error) {
  program_ = shaderProgram(QStringLiteral(":/microsim/shaders/eyepiece.vert"),
                           QStringLiteral(":/microsim/shaders/eyepiece.frag"),
                           softwareRenderer ? QByteArray("#define TAP_STEP 2\n") : QByteArray(), error);
  if (program_)
    mask_ = shaderProgram(QStringLiteral(":/microsim/shaders/field_mask.vert"),
                          QStringLiteral(":/microsim/shaders/field_mask.frag"), {}, error);
  if (!program_ || !mask_ || !empty_.create() || !maskArray_.create() || !maskVertices_.create()) {
    destroy();
    return false;
  }
  return true;
}

void EyepiecePass::destroy() {
  program_.reset();
  mask_.reset();
  maskVertices_.destroy();
  maskArray_.destroy();
  multisampled_.reset();
  picture_.reset();
  empty_.destroy();
}

void EyepiecePass::maskOutsideField(QOpenGLExtraFunctions& gl, const QRect& area) {
  const std::vector<float> triangles = fieldMaskTriangles(area);
  QOpenGLVertexArrayObject::Binder bind(&maskArray_);
  maskVertices_.bind();
  maskVertices_.allocate(triangles.data(), static_cast<int>(triangles.size() * sizeof(float)));
  gl.glEnableVertexAttribArray(0);
  gl.glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, static_cast<GLsizei>(2 * sizeof(float)), nullptr);
  mask_->bind();
  gl.glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(triangles.size() / 2));
  mask_->release();
}

bool EyepiecePass::begin(QOpenGLExtraFunctions& gl, const QSize& size, int samples) {
  if (!picture_ || picture_->size() != size) {
    picture_ = pictureTarget(size, 0);
    multisampled_.reset();
  }
  if (samples == 0) multisampled_.reset();
  if (samples > 0 && (!multisampled_ || samples_ != samples)) multisampled_ = pictureTarget(size, samples);
  samples_ = samples;
  QOpenGLFramebufferObject* target = multisampled_ ? multisampled_.get() : picture_.get();
  if (!target->isValid()) return false;
  gl.glBindFramebuffer(GL_FRAMEBUFFER, target->handle());
  return true;
}

void EyepiecePass::finish(QOpenGLExtraFunctions& gl, unsigned target, const QRect& area, float blur) {
  if (multisampled_)
    QOpenGLFramebufferObject::blitFramebuffer(picture_.get(), area, multisampled_.get(), area, GL_COLOR_BUFFER_BIT);
  gl.glBindFramebuffer(GL_FRAMEBUFFER, target);
  gl.glViewport(area.x(), area.y(), area.width(), area.height());
  gl.glDisable(GL_DEPTH_TEST);
  QOpenGLShaderProgram* program = program_.get();
  program->bind();
  gl.glActiveTexture(GL_TEXTURE0);
  gl.glBindTexture(GL_TEXTURE_2D, picture_->texture());
  program->setUniformValue("picture", 0);
  gl.glUniform4i(program->uniformLocation("area"), area.x(), area.y(), area.width(), area.height());
  program->setUniformValue("maxBlur", blur);
  {
    QOpenGLVertexArrayObject::Binder bind(&empty_);
    gl.glDrawArrays(GL_TRIANGLES, 0, 3);
  }
  program->release();
  gl.glBindTexture(GL_TEXTURE_2D, 0);
  gl.glEnable(GL_DEPTH_TEST);
}

}  // namespace microsim::gui
