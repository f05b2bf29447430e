#pragma once
// The SO(3) helpers live in the base layer (base/so3.h), shared by nav and vision. This header remains
// only for board/replay, which still includes it by this path.
#include "base/so3.h"
