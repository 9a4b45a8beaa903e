# Every external package microsim uses; all come from Debian (scripts/install-deps.sh).
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(nlohmann_json 3.10 REQUIRED)
find_package(assimp REQUIRED)
find_package(Qt6 6.4 REQUIRED COMPONENTS Core Sql Gui Widgets OpenGL OpenGLWidgets Network Charts LinguistTools Test)
find_package(Threads REQUIRED)
# OpenSubdiv (Debian libosd-dev): Loop subdivision of the drawn tissue surface
# (mesh/smooth_surface.h). Debian's CMake package names static libraries it does not ship,
# so the header and the CPU library are found by hand, as one imported target.
find_path(OPENSUBDIV_INCLUDE_DIR opensubdiv/far/topologyRefiner.h REQUIRED)
find_library(OPENSUBDIV_CPU_LIBRARY NAMES osdCPU REQUIRED)
add_library(microsim_opensubdiv INTERFACE IMPORTED)
target_include_directories(microsim_opensubdiv SYSTEM INTERFACE ${OPENSUBDIV_INCLUDE_DIR})
target_link_libraries(microsim_opensubdiv INTERFACE ${OPENSUBDIV_CPU_LIBRARY})
# OpenIGTLink (Debian libopenigtlink-dev) has no imported target: OpenIGTLink_INCLUDE_DIRS, _LIBRARIES
find_package(OpenIGTLink REQUIRED PATHS /usr/lib/openigtlink)
# 6-DoF input devices people own: game controllers through SDL2 (libsdl2-dev, a CMake
# package), 3D mice through libspnav (libspnav-dev: a header and libspnav.so in /usr/lib, no
# CMake or pkg-config file)
find_package(SDL2 REQUIRED CONFIG)
find_path(SPNAV_INCLUDE_DIR spnav.h REQUIRED)
find_library(SPNAV_LIBRARY NAMES spnav REQUIRED)

if(MICROSIM_BUILD_TESTS)
  find_package(GTest REQUIRED)
  include(GoogleTest)
endif()

include(GNUInstallDirs)
