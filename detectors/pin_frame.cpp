#include "detectors/pin_frame.h"
