// Translation unit of the target that owns the precompiled header (see
// cmake/precompiled_headers.h); it has no code of its own.
