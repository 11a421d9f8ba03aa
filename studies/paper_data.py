"""The source paper's published numbers that studies/paper_layups.py compares against
("Modeling of static indentation on laminated composite shells"). Units and the
angle unit of eqs 82-85 are not stated in the paper (paper-notes.md item 6).
"""

# Table 2: (C1, C2) of T_N = C1 h^C2 (eq 81) per lay-up; N and mm assumed.
TABLE2 = {
    "[0/0]2S": (327.9442, 0.7021), "[15/-15]2S": (390.0318, 0.7128),
    "[30/-30]2S": (481.8368, 0.7286), "[45/-45]2S": (555.2646, 0.7130),
    "[60/-60]2S": (582.3713, 0.6987), "[75/-75]2S": (602.1435, 0.7043),
    "[90/-90]2S": (564.8069, 0.7019), "[0/90]2S": (533.0893, 0.7137),
}
# Eqs 82, 83, 85: coefficients a0, a1, a2, ... of the powers of theta.
EQ82_C1 = [545.86, 127.14, -52.774, -21.222]
EQ83_C2 = [0.71, -0.02, -0.0063, 0.011]
EQ85_ENERGY_J = [350.0, 330.0, -150.0, -250.0, 14.0, 61.0, 7.1]  # "E_indt (J)", 0 -> 10 mm
