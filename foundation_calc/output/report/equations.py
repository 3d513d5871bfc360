"""The equations a calculation sheet quotes, with their sources and fcalc's corrections of the print.

Sources: [KM] Krichever & Makarov, foundation of a crank mechanism; [BC] Bolotnik, Gusev, Nguyen,
Kholmin, Chernousko, vibrating platform. The corrections are those listed in docs/theory.md, section
"Corrections to the sources".
"""

from __future__ import annotations

from foundation_calc.output.report.model import Equation

CRANK = (
    Equation(
        'k_0^2 = c S / M_"tot", quad a_0 = c_1 S / M_"tot", quad b_0 = c_1 h S / M_"tot", quad'
        ' a_1 = c_1 h S / I_c, quad b_1 = (c_1 h^2 S + c_phi I_1 - P_"tot" h) / I_c',
        "k0² = c S/M_tot, a0 = c1 S/M_tot, b0 = c1 h S/M_tot, a1 = c1 h S/I_c,"
        " b1 = (c1 h² S + c_φ I1 − P_tot h)/I_c",
        "[KM] Eq. (4.5), with (3.4)",
        "(3.4): the weight term of the rocking stiffness is −P h (printed +P h); ∫z³ is ∫z²;"
        " the paper's c I1 is generalised to c_φ I1 (c_φ = c unless soil.c_phi is given).",
    ),
    Equation(
        'p_(1,2)^2 = (a_0 + b_1)/2 minus.plus sqrt(((a_0 + b_1)/2)^2 - (a_0 b_1 - a_1 b_0))',
        "p1², p2² = (a0 + b1)/2 ∓ sqrt(((a0 + b1)/2)² − (a0 b1 − a1 b0))",
        "[KM] Eq. (4.7)",
        "(4.6)–(4.9): the printed ρ1, ρ2 are the frequencies p1, p2; the smaller root is computed as"
        " (a0 b1 − a1 b0)/p2² to avoid cancellation.",
    ),
    Equation(
        'omega = k_0, quad 2 omega = k_0, quad omega = p_(1,2), quad 3 omega = p_(1,2)'
        ' quad "(and 4" omega = k_0", 2" omega = p_(1,2) ")"',
        "resonances ω = k0, 2ω = k0, ω = p1,2, 3ω = p1,2 (and 4ω = k0, 2ω = p1,2)",
        "[KM] §4; the bracketed conditions are resonances of the exact equations",
    ),
    Equation(
        'y_c = "Re" mu [ (r omega^2)/(k_0^2 - omega^2 + i omega zeta_z) e^(i omega t)'
        " + (l')/l lambda (r omega^2)/(k_0^2 - 4 omega^2 + 2 i omega zeta_z) e^(2 i omega t) ],"
        ' quad zeta_z = C_z / M_"tot", quad m = m_"rod" + m_1, quad l\' = (m_"rod" l\'_"rod" + m_1 l)/m',
        "y_c = Re μ [ r ω²/(k0² − ω² + i ω ζ_z) e^{iωt} + (l'/l) λ r ω²/(k0² − 4ω² + 2i ω ζ_z) e^{2iωt} ],"
        "  ζ_z = C_z/M_tot;  m = m_rod + m1, l' = (m_rod l'_rod + m1 l)/m: the rod with the slider lumped in  (y down)",
        "[KM] Eqs. (4.11), (4.14), last paragraph; the base dashpot C_z added",
        "(4.14): μ multiplies the solution of (4.11) once (read literally, the print counts it"
        " twice and gives amplitudes about 70× too small). μ = m/M_tot, l' and κ = l'l'' − ρ² are"
        " those of rod and slider together (ρ² = [m_rod (ρ_rod² + (l'_rod − l')²) + m1 (l − l')²]/m);"
        " the hand calculation under Methods substitutes the numbers.",
    ),
    Equation(
        "x_c = mu [ b' sin omega t + b''' sin 3 omega t ], quad"
        " theta = mu [ c' sin omega t + c''' sin 3 omega t ]",
        "x_c = μ [ b' sin ωt + b''' sin 3ωt ],  θ = μ [ c' sin ωt + c''' sin 3ωt ]",
        "[KM] Eqs. (4.11)–(4.14)",
        "(4.12): A′ lacks 1/l on the crank term and has the wrong sign on the rod-couple term;"
        " (4.13): A‴ has the wrong sign; \"c_1\" in (4.14) is θ1. With base dashpots b′, c′ (b‴, c‴) are the"
        " complex solutions of the damped (4.11): X = (D F_x + B F_θ)/Δ, Θ = (C F_x + A F_θ)/Δ with"
        " A = a0 − W² + i W γ_x, B = b0 + i W h γ_x, C = a1 + i W h γ_θ, D = b1 − W² + i W (h² γ_θ + γ_φ),"
        " Δ = A D − B C, W = nω, γ_x = C_x/M_tot, γ_θ = C_x/I_c, γ_φ = C_φ/I_c; m, l′, ρ of rod and slider together.",
    ),
)

#: The plane model of a crank on a support coupling sway with rocking (a pile group), where (4.5)-(4.14)
#: do not apply: its frequencies (:mod:`~foundation_calc.output.report.plane_support`) and damped solve.
PLANE = (
    Equation(
        'k_0^2 = K_z / M_"tot", quad A_2 p^4 - A_1 p^2 + A_0 = 0, quad'
        ' A_2 = M_"tot" macron(M)_(theta theta) - macron(M)_(x theta)^2, quad'
        ' A_1 = K_x macron(M)_(theta theta) + macron(K)_(theta theta) M_"tot" - 2 macron(K)_(x theta) macron(M)_(x theta), quad'
        ' A_0 = K_x macron(K)_(theta theta) - macron(K)_(x theta)^2',
        "k0² = K_z/M_tot;  A2 p⁴ − A1 p² + A0 = 0 (det(K̄ − p² M̄) = 0 in x, θ about C): A2 = M_tot M̄_θθ − M̄_xθ²,"
        " A1 = K_x M̄_θθ + K̄_θθ M_tot − 2 K̄_xθ M̄_xθ, A0 = K_x K̄_θθ − K̄_xθ²;  K̄_xθ = K_xφ − h K_x,"
        " K̄_θθ = K_φ − 2h K_xφ + h² K_x − P h − g M̄_xθ",
        "plane model about C with the mechanism's inertia averaged over a revolution; K at O of the support, coupled"
        " (u_x = x − h θ); [KM] (3.4) for −P h",
    ),
    CRANK[2],
    Equation(
        '(macron(K) - n^2 omega^2 macron(M) + i n omega macron(C)) Z_n = F_n',
        "(K̄ − n²ω² M̄ + i nω C̄) Z_n = F_n, harmonic by harmonic, C̄ with the support's C_xφ",
        "averaged operator: the exact equations linearised about rest and averaged over a revolution, F_n the exact"
        " forcing's Fourier coefficients",
    ),
)

LOADS = (
    Equation(
        '(K - n^2 omega^2 M + i n omega C) Z_n = sum Q e^(i phi), quad'
        ' Q = (F_x, F_y, H F_x + u F_y + M)',
        "(K − n²ω² M + i nω C) Z_n = Σ Q e^{iφ},  Q = (F_x, F_y, H F_x + u F_y + M)  (loads F cos(nωt + φ) at (u, H) from C)",
        "vendor loads: rigid block about C, K of [KM] (3.2)–(3.4) corrected, C the base dashpots",
    ),
)

PLATFORM = (
    Equation(
        'c_0 = c_1 = c_2 = M_Sigma omega^2 plus.minus (m l omega^2) / u',
        "c0 = c1 = c2 = M_Σ ω² ± m l ω²/u  (+ below, − above resonance; u the required amplitude)",
        "[BC] Eq. (3.14)",
    ),
    Equation(
        'c = (omega^2 g M_Sigma - g c_0 - M omega^4 zeta) / (omega^2 (c_0 - M omega^2))',
        "c = (ω² g M_Σ − g c0 − M ω⁴ ζ) / (ω² (c0 − M ω²)), c0 ≠ M ω²; a, b from (3.9), (3.10)",
        "[BC] Eqs. (3.9)–(3.11)",
        "(3.2), (3.5), (3.11), (3.15): the printed ξ is ζ, the height of the centre of mass.",
    ),
    Equation(
        'c_(i j) "from the pair sums", quad c_13 = (M + 4 m) K / M',
        "c_ij from the pair sums; c13 = (M + 4m) K/M",
        "[BC] Eqs. (3.16)–(3.21)",
        "(3.21): c13 = (M+4m)K/M = 1.005·10⁸ N/m in the example (printed 4.005·10⁸, which is c3).",
    ),
    Equation(
        'M(t) dot.double(q) + G(t) dot(q) + K(t) q = F(t), quad q = (x, y, z, alpha, beta, gamma)',
        "M(t) q'' + G(t) q' + K(t) q = F(t),  q = (x, y, z, α, β, γ): corner O1's displacement and the platform's rotation",
        "[BC] Eqs. (1.1)-(1.9), re-derived (6-DOF verification)",
        "the printed rotational equations are omitted and the rotor matrix A_j(φ) is garbled (its entry (3,2) is"
        " −sin δ2 cos φ); K holds the isolators' K_springs = Σ T_iᵀ diag(c_i1, c_i2, c_i3) T_i and the weight's tilt.",
    ),
    Equation(
        'D(Omega_m) Q_m + sum_(k != 0) A_k (Omega_(m-k)) Q_(m-k) = F_m - K_m q_s, quad'
        ' D(Omega) = K_0 + i (eta "sgn" Omega + beta Omega) K_"springs" + i Omega G_0 - Omega^2 M_0',
        "D(Ω_m) Q_m + Σ_{k≠0} A_k(Ω_{m−k}) Q_{m−k} = F_m − K_m q_s,  D(Ω) = K_0 + i(η sgn Ω + β Ω) K_springs + iΩ G_0 − Ω² M_0",
        "harmonic balance over the rotors' combination frequencies Ω_n = n·ω (6-DOF verification)",
        "harmonics are added while the estimate of a left-out one exceeds 10⁻¹² of the largest; the estimates"
        " left out, summed as peaks, are the truncation error on the sheet.",
    ),
    Equation(
        'z = - M_Sigma g / c_3',
        "z = −M_Σ g / c3",
        "[BC] static deflection",
        "printed without the sign.",
    ),
)
