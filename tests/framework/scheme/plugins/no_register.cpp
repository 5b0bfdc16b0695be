// The ABI symbol without a registration function.
#include "framework/scheme/plugin.h"

COOPERAGE_PLUGIN_ABI
