// Mesa's off-screen rasteriser, loaded at the first render instead of at program start:
// libOSMesa pulls in libLLVM, whose loading and relocation cost about a third of a second, and
// most runs (`feedflow design`, `version`) draw nothing. The program does not link libOSMesa;
// the four OSMesa functions the renderer calls are defined here as forwarders (see
// models/os/shared_library.hpp), and the OpenGL ones are looked up through OSMesaGetProcAddress
// (gl_api.hpp). Without the library the first render throws NotAvailable (exit code 3).
#include <GL/osmesa.h>

#include "models/os/shared_library.hpp"

namespace {

const feedflow::SharedLibrary& osmesa() {
  static const feedflow::SharedLibrary library({"libOSMesa.so.8", "libOSMesa.so"}, "libosmesa6",
                                               "off-screen rendering (snapshots, report pictures)");
  return library;
}

}  // namespace

FEEDFLOW_FORWARD(osmesa(), OSMesaContext, OSMesaCreateContextAttribs,
                 (const int* attributes, OSMesaContext share), (attributes, share))
FEEDFLOW_FORWARD(osmesa(), void, OSMesaDestroyContext, (OSMesaContext context), (context))
FEEDFLOW_FORWARD(osmesa(), GLboolean, OSMesaMakeCurrent,
                 (OSMesaContext context, void* buffer, GLenum type, GLsizei width, GLsizei height),
                 (context, buffer, type, width, height))
FEEDFLOW_FORWARD(osmesa(), OSMESAproc, OSMesaGetProcAddress, (const char* name), (name))
