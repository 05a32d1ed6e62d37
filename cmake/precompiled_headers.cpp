// Translation unit of the target that owns the precompiled header (see
// cmake/precompiled_headers.h), and the one place where the shared instances
// declared in cmake/shared_instances.h are compiled; every program that
// reuses the precompiled header links this object.
#include "shared_instances.h"

#define CUT_PARAM_DEFINE_SHARED_INSTANCE(...) CUT_PARAM_SHARED_INSTANCE(, __VA_ARGS__)
CUT_PARAM_FOR_EACH_SHARED_MESH(CUT_PARAM_DEFINE_SHARED_INSTANCE)
