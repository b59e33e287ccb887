// Errors the framework reports in one line. main() maps each kind to an exit code.
#pragma once
#include <stdexcept>
#include <string>

namespace stencil {

// Bad input from the user: unknown flag, missing shader, shader that fails to compile,
// framebuffer without stencil, missing feature. Exit code 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// An output file or folder that cannot be written: the message names the path and the
// system's reason. Bad input too, so exit code 2.
struct OutputError : UsageError {
  using UsageError::UsageError;
};

// No GL context could be created at all. Exit code 77, which golden tests report as skipped.
struct NoContextError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A GL error or a debug-output error during rendering. Exit code 1: a bug, not bad input.
struct GlError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace stencil
