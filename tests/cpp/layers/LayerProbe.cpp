// Includes the one header named by SBSIM_PROBE_HEADER, compiled with one layer's include path:
// the layer tests show that a layer reaches its own headers and those below, and nothing above.
#include SBSIM_PROBE_HEADER
