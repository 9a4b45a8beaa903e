#include "gui/render/shader_program.h"

#include <QFile>
#include <QOpenGLShaderProgram>

namespace microsim::gui {

namespace {

// the source at `path` with `defines` after its first line (the #version line)
QByteArray shaderSource(const QString& path, const QByteArray& defines) {
  QFile file(path);
  if (!file.open(QIODevice::ReadOnly)) return {};
  QByteArray source = file.readAll();
  const qsizetype firstLine = source.indexOf('\n');
  if (firstLine >= 0) source.insert(firstLine + 1, defines);
  return source;
}

}  // namespace

std::unique_ptr<QOpenGLShaderProgram> shaderProgram(const QString& vertex, const QString& fragment,
                                                    const QByteArray& defines, QString* error) {
  auto program = std::make_unique<QOpenGLShaderProgram>();
  const bool ok = program->addShaderFromSourceCode(QOpenGLShader::Vertex, shaderSource(vertex, defines)) &&
                  program->addShaderFromSourceCode(QOpenGLShader::Fragment, shaderSource(fragment, defines)) &&
                  program->link();
  if (!ok) {
    if (error) *error = program->log();
    return nullptr;
  }
  return program;
}

}  // namespace microsim::gui
