#pragma once
// A linked shader program from the app's resources, with preprocessor definitions put after
// the `#version` line: one source, several variants. Variants instead of run-time branches:
// a software rasteriser (llvmpipe) runs both sides of a branch for every pixel, so a tissue
// shader behind an `if` would cost its noise on the whole drape.

#include <QByteArray>
#include <QString>

#include <memory>

class QOpenGLShaderProgram;

namespace microsim::gui {

/// The program of vertex shader `vertex` and fragment shader `fragment` (resource paths),
/// each compiled with `defines` (e.g. "#define TISSUE_WALL\n"); null with `error` set when it
/// does not compile or link. Needs a current context.
std::unique_ptr<QOpenGLShaderProgram> shaderProgram(const QString& vertex, const QString& fragment,
                                                    const QByteArray& defines, QString* error);

}  // namespace microsim::gui
