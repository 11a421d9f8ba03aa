"""The result columns of path.csv, path.json and path_grid.csv (docs/results.md),
generated from src/analysis/path_columns.cpp by scripts/update_schema.sh: do not edit.
tests/io/test_column_tables.cpp fails if this file and the table differ. The study
scripts read columns by these names.
"""

DEPTH_MM = "depth_mm"
FORCE_N = "force_N"
REACTION_N = "reaction_N"
APEX_W_MM = "apex_w_mm"
CONTACT_RADIUS_MM = "contact_radius_mm"
CONTACT_AREA_MM2 = "contact_area_mm2"
CONTACT_NODES = "contact_nodes"
K11_PER_MM = "k11_per_mm"
K12_PER_MM = "k12_per_mm"
K22_PER_MM = "k22_per_mm"
ENERGY_NMM = "energy_Nmm"
WORK_NMM = "work_Nmm"
MIN_GAP_MM = "min_gap_mm"
MIN_MULTIPLIER_N = "min_multiplier_N"
MAX_COMPLEMENTARITY_NMM = "max_complementarity_Nmm"
ITERATIONS = "iterations"
STEP = "step"
LOCAL_INDENT_MM = "local_indent_mm"
LOCAL_ENERGY_NMM = "local_energy_Nmm"
K11_CONTACT_MIN_PER_MM = "k11_contact_min_per_mm"
K11_CONTACT_MAX_PER_MM = "k11_contact_max_per_mm"
K12_CONTACT_MIN_PER_MM = "k12_contact_min_per_mm"
K12_CONTACT_MAX_PER_MM = "k12_contact_max_per_mm"
K22_CONTACT_MIN_PER_MM = "k22_contact_min_per_mm"
K22_CONTACT_MAX_PER_MM = "k22_contact_max_per_mm"
ERROR_ESTIMATE = "error_estimate"
FRAME_FORCE_N = "frame_force_N"
APEX_MID_W_MM = "apex_mid_w_mm"
FORCE_ERROR_ESTIMATE = "force_error_estimate"
MAX_STRESS_INDEX = "max_stress_index"
TSAI_WU_INDEX = "tsai_wu_index"
HASHIN_INDEX = "hashin_index"
DELAMINATION_INDEX = "delamination_index"
STABLE = "stable"
LOWEST_EIGENVALUE = "lowest_eigenvalue"
BRANCH = "branch"

# All columns, in path.csv's order.
PATH_COLUMNS = (
    DEPTH_MM,
    FORCE_N,
    REACTION_N,
    APEX_W_MM,
    CONTACT_RADIUS_MM,
    CONTACT_AREA_MM2,
    CONTACT_NODES,
    K11_PER_MM,
    K12_PER_MM,
    K22_PER_MM,
    ENERGY_NMM,
    WORK_NMM,
    MIN_GAP_MM,
    MIN_MULTIPLIER_N,
    MAX_COMPLEMENTARITY_NMM,
    ITERATIONS,
    STEP,
    LOCAL_INDENT_MM,
    LOCAL_ENERGY_NMM,
    K11_CONTACT_MIN_PER_MM,
    K11_CONTACT_MAX_PER_MM,
    K12_CONTACT_MIN_PER_MM,
    K12_CONTACT_MAX_PER_MM,
    K22_CONTACT_MIN_PER_MM,
    K22_CONTACT_MAX_PER_MM,
    ERROR_ESTIMATE,
    FRAME_FORCE_N,
    APEX_MID_W_MM,
    FORCE_ERROR_ESTIMATE,
    MAX_STRESS_INDEX,
    TSAI_WU_INDEX,
    HASHIN_INDEX,
    DELAMINATION_INDEX,
    STABLE,
    LOWEST_EIGENVALUE,
    BRANCH,
)

UNITS = {
    DEPTH_MM: "mm",
    FORCE_N: "N",
    REACTION_N: "N",
    APEX_W_MM: "mm",
    CONTACT_RADIUS_MM: "mm",
    CONTACT_AREA_MM2: "mm^2",
    CONTACT_NODES: "-",
    K11_PER_MM: "1/mm",
    K12_PER_MM: "1/mm",
    K22_PER_MM: "1/mm",
    ENERGY_NMM: "N mm",
    WORK_NMM: "N mm",
    MIN_GAP_MM: "mm",
    MIN_MULTIPLIER_N: "N",
    MAX_COMPLEMENTARITY_NMM: "N mm",
    ITERATIONS: "-",
    STEP: "mm",
    LOCAL_INDENT_MM: "mm",
    LOCAL_ENERGY_NMM: "N mm",
    K11_CONTACT_MIN_PER_MM: "1/mm",
    K11_CONTACT_MAX_PER_MM: "1/mm",
    K12_CONTACT_MIN_PER_MM: "1/mm",
    K12_CONTACT_MAX_PER_MM: "1/mm",
    K22_CONTACT_MIN_PER_MM: "1/mm",
    K22_CONTACT_MAX_PER_MM: "1/mm",
    ERROR_ESTIMATE: "-",
    FRAME_FORCE_N: "N",
    APEX_MID_W_MM: "mm",
    FORCE_ERROR_ESTIMATE: "-",
    MAX_STRESS_INDEX: "-",
    TSAI_WU_INDEX: "-",
    HASHIN_INDEX: "-",
    DELAMINATION_INDEX: "-",
    STABLE: "-",
    LOWEST_EIGENVALUE: "N/mm",
    BRANCH: "-",
}
