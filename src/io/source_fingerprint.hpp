#pragma once

namespace si {

// The SHA-256 of the sources and build settings this binary was built from (computed by the build,
// cmake/SourceFingerprint.cmake). path.json records it (`build.source_fingerprint`); a sweep runs
// a case again when another build wrote its results, so a rerun after a code change never keeps
// stale results (io/sweep_table.hpp, case_state).
const char* source_fingerprint();

}  // namespace si
