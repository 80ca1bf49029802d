#pragma once
// The consumer's own core/errors.h: a name that collides with bezierpde's core/errors.h unless
// bezierpde's headers live under bezierpde/ (tests/package).
namespace consumer {
inline constexpr bool kOwnCoreErrors = true;
}  // namespace consumer
