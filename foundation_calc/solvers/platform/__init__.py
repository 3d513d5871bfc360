"""Vibrating platform with unbalanced exciters (Bolotnik, Chernousko et al.): design and 6-DOF dynamics."""
