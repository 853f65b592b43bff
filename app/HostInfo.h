#pragma once
// Moved to renderer/record/HostInfo.h (the experiment records are the library's now).
#include "renderer/record/HostInfo.h"
