# pure-move split of fem/fem_rom.c into fem_rom.c, fem_rom_eval.c, fem_rom_newton.c
import re, sys
src = open('fem/fem_rom.c').read().split('\n')
L = lambda a, b: src[a-1:b]          # 1-based inclusive
body_model = L(34, 443)              # fibreOperators .. csf_romDataDestroy (before blank+eval marker)
body_eval = L(447, 997)              # after "---- evaluation" marker .. end of csf_romElementForces
body_newton = L(1001, len(src))      # after "---- Newton" marker
assert src[444].startswith('/* ---- evaluation'), src[444]
assert src[998].startswith('/* ---- Newton'), src[998]
assert src[28:33] == ['', '#define ROM_LS_SHRINK 0.5 /* line-search step factor */',
    '/* the FE\'s watchdog line search (fem_newton.c CSF_LS_GROWTH_FIRST, CSF_LS_WATCH) */',
    '#define ROM_LS_GROWTH_FIRST 1e4', '#define ROM_LS_WATCH 3'], src[28:33]
macros = src[29:33]
def ren(lines):
    t = '\n'.join(lines)
    t = re.sub(r'\bstatic void chamberHessian\(', 'void csf_romChamberHessian(', t)
    t = re.sub(r'\bchamberHessian\(', 'csf_romChamberHessian(', t)
    t = re.sub(r'\bstatic void gather\(', 'void csf_romGather(', t)
    t = re.sub(r'(?<![A-Za-z_>.])gather\(', 'csf_romGather(', t)
    return t.strip('\n')
head_model = '''/* fem_rom.c: the reduced-order FE model (fem_rom.h): the basis V and its element sets and
 * weights, the kept fibres' chord operators, the gravity projection G, the chambers' volume
 * tensors, and the per-solve data (csfRomData). The evaluation of the reduced forces is
 * fem_rom_eval.c, the reduced Newton fem_rom_newton.c; what they share with this file is
 * declared in fem_rom_internal.h.
 *
 * Rationale.
 * Gravity and dead loads are linear in the load and constant in q, so they are projected once,
 * exactly, over every element (G, here at creation) and never hyper-reduced. */
#include "fem_rom.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fem_element.h"
#include "fem_material.h"
#include "fem_rom_fibre.h"
#include "fem_rom_internal.h"
#include "fem_rom_mixed.h"
'''
head_eval = '''/* fem_rom_eval.c: the evaluation of the reduced-order FE model (fem_rom.h): the reduced
 * residual and tangent from fem's kernels (csf_romEvaluate) and every element's reduced force
 * (csf_romElementForces, ECSW's training matrix). The model and its data are fem_rom.c, the
 * Newton on q fem_rom_newton.c.
 *
 * Rationale.
 * Every element term is gathered through its own rows of the basis: u_e = V_e q (30 rows for a
 * Tet10 or a fibre inside one host, 60 for a fibre tied to two, 18 for a pressure face), the
 * kernel gives f_e and k_e, and r += w_e V_e^T f_e, K += w_e V_e^T k_e V_e. The cost per element
 * is O(m n + m^2 n + m n^2) for m element dofs and n reduced coordinates, independent of the
 * FE's size: a hyper-reduced model evaluates a few hundred elements instead of tens of
 * thousands. Gravity and dead loads are projected once, exactly, over every element (G,
 * fem_rom.c) and never hyper-reduced: here they are only added.
 * The kernels' state variables: the mixed Tet10 takes the element dilatation state theta_e in
 * its geometric stiffness; here theta_e = v/V of the current q (one residual-only kernel call
 * gives v/V, a second one the tangent), the converged value of the FE's three-field Newton, so
 * the reduced tangent is the exact derivative of the reduced residual (tested against finite
 * differences). The fibres likewise take S_state = S(E(q)). */
#include "fem_rom.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fem_element.h"
#include "fem_material.h"
#include "fem_rom_fibre.h"
#include "fem_rom_internal.h"
#include "fem_rom_mixed.h"
'''
head_newton = '''/* fem_rom_newton.c: the reduced Newton on q (fem_rom.h csf_romNewton): the dense LU of the
 * reduced tangent, the line search, the element states' update along a step, and the
 * quasi-Newton (BFGS) pairs. The residual and tangent it solves with are fem_rom_eval.c's
 * csf_romEvaluate; the model and its data are fem_rom.c.
 *
 * Rationale.
 * The dense n x n system is solved by LU with partial pivoting (n is tens to a few hundred; the
 * tangent may be indefinite past a limit point). The element states (theta_e, the fibres' S)
 * follow the step as the FE's three-field Newton does (fem_rom_eval.c says why they are the
 * kernels' state variables). */
#include "fem_rom.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fem_element.h"
#include "fem_material.h"
#include "fem_rom_fibre.h"
#include "fem_rom_internal.h"
#include "fem_rom_mixed.h"

''' + '\n'.join(macros) + '\n'
open('fem/fem_rom.c', 'w').write(head_model + '\n' + ren(body_model) + '\n')
open('fem/fem_rom_eval.c', 'w').write(head_eval + '\n' + ren(body_eval) + '\n')
open('fem/fem_rom_newton.c', 'w').write(head_newton + '\n' + ren(body_newton) + '\n')
