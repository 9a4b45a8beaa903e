#pragma once
// The eyepiece: what the microscope's oculars make of the lit picture.
//   - The circular field of view (eyepieceField): black outside a circle as wide as the eye's
//     area's smaller side, a soft edge and a slight fall-off toward it. The lit pass applies it
//     per fragment (resources/shaders/shaded.frag: free, where a full-screen pass of its own
//     would cost a software rasteriser a good part of its frame rate), after maskOutsideField has put a
//     ring of triangles on the near plane over everything outside the circle: the scene's
//     fragments there fail the early depth test and are never shaded (half of a 16:10 picture).
//   - Depth of field (this pass, only while it is on): the viewport draws each eye's scene into
//     an offscreen picture (begin), each pixel's out-of-focus amount in its alpha, and this pass
//     draws it into the widget (finish), pixels off the focal plane blurred by a disc of taps
//     whose radius grows with that amount (resources/shaders/eyepiece.frag). On a software
//     rasteriser the disc has half the taps (render/renderer_probe.h).
// The side view is no microscope: the viewport draws it after this pass, straight into the
// widget, unblurred and without the field stop.
//
// On a GPU the offscreen picture is multisampled as the widget is, then resolved; without
// multisampling it is drawn into directly. Measured on llvmpipe at 1280×800 (README, Viewport
// speed).
//
// Units: pixels of the framebuffer (device pixels), GL's origin at the bottom left.

#include <QOpenGLBuffer>
#include <QOpenGLVertexArrayObject>
#include <QPointF>
#include <QRect>
#include <QSize>
#include <QString>

#include <memory>
#include <vector>

class QOpenGLExtraFunctions;
class QOpenGLFramebufferObject;
class QOpenGLShaderProgram;

namespace microsim::gui {

/// The field stop of an eye's area.
struct EyepieceField {
  QPointF centre;      ///< pixels
  float radius = 0.0f; ///< where the field is black (half the area's smaller side)
  float edge = 0.0f;   ///< width of the soft edge inside the radius
};

EyepieceField eyepieceField(const QRect& area);

/// The ring from the field stop's circle to beyond the corners of `area`, as triangles (two
/// floats a vertex, normalised device coordinates of the area's viewport), `segments` round.
std::vector<float> fieldMaskTriangles(const QRect& area, int segments = 64);

/// Pixels of blur for a fully out-of-focus point in an eye's area `height` pixels tall.
float maxBlurPixels(int height);

class EyepiecePass {
 public:
  EyepiecePass();
  ~EyepiecePass();
  EyepiecePass(const EyepiecePass&) = delete;
  EyepiecePass& operator=(const EyepiecePass&) = delete;

  /// Compiles the pass's program (a current context needed), the cheaper disc for a
  /// `softwareRenderer`; false with `error` set if it does not compile.
  bool create(bool softwareRenderer, QString* error);
  void destroy();
  bool isCreated() const { return program_ != nullptr; }

  /// Draws the field stop's mask over `area` (the current viewport) on the near plane, in
  /// black: depth test and writes on.
  void maskOutsideField(QOpenGLExtraFunctions& gl, const QRect& area);

  /// Binds the offscreen picture, `size` pixels with `samples` (the widget's), for the lit
  /// pass; made or remade when either changes.
  bool begin(QOpenGLExtraFunctions& gl, const QSize& size, int samples);
  /// Draws `area` of the picture into framebuffer `target`, blurred by up to `blur` pixels;
  /// leaves `target` bound.
  void finish(QOpenGLExtraFunctions& gl, unsigned target, const QRect& area, float blur);

 private:
  std::unique_ptr<QOpenGLShaderProgram> program_;
  std::unique_ptr<QOpenGLShaderProgram> mask_;
  QOpenGLVertexArrayObject maskArray_;
  QOpenGLBuffer maskVertices_{QOpenGLBuffer::VertexBuffer};
  std::unique_ptr<QOpenGLFramebufferObject> multisampled_;  // drawn into on a GPU, then resolved
  std::unique_ptr<QOpenGLFramebufferObject> picture_;       // what the pass samples
  int samples_ = 0;                                         // asked of multisampled_
  QOpenGLVertexArrayObject empty_;  // the core profile draws nothing without a bound array
};

}  // namespace microsim::gui
