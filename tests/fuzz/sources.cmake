# The sources the two fuzz targets link: only what the readers need, so that the sanitized fuzz
# build takes a minute, not the whole toolkit. Shared by tests/fuzz/CMakeLists.txt (clang,
# libFuzzer) and tests/CMakeLists.txt, whose ordinary build links each harness against exactly
# this list with a replay main (tests/fuzz/replay_main.cpp): a reader that gains a dependency
# then fails the ordinary build at once instead of the fuzz stage at the end of CI.
set(SHELLINDENT_FUZZ_SOURCES
    core/decimal_number.cpp core/error.cpp core/units.cpp core/value_excerpt.cpp
    core/did_you_mean.cpp damage/criterion_strengths.cpp analysis/path_spec.cpp io/case_file.cpp
    io/damage_reader.cpp io/fixture_reader.cpp io/fraction_reader.cpp io/laminate_reader.cpp
    io/material_reader.cpp io/named_sets_reader.cpp io/output_reader.cpp io/path_reader.cpp
    io/plausible_range.cpp
    io/spellings.cpp io/yaml_reader.cpp model/fixture.cpp
    model/mesh.cpp
    material/material.cpp material/material_library.cpp material/ply_rotation.cpp
    material/ply_strengths.cpp
    section/laminate.cpp section/layup_notation.cpp)
list(TRANSFORM SHELLINDENT_FUZZ_SOURCES PREPEND ${PROJECT_SOURCE_DIR}/src/)
