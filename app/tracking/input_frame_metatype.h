#pragma once
// The engine's InputFrame as a Qt metatype, declared once for every file that queues it across
// threads (tracker sources, the simulation runner): a file that used the type in a queued call
// before seeing the declaration would instantiate another QMetaTypeId for it.
#include "microsim/sim/scene/input_frame.h"

#include <QMetaType>

Q_DECLARE_METATYPE(microsim::sim::InputFrame)
