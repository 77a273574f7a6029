# Included from tests/cases/CMakeLists.txt (CASES, RUN, PYTHON3, case_test).
# Fixed fiber mats across four ducts at steady plug flow, solid fractions 0.5, 1, 2,
# 3 %, their drag on the air (fibers.coupled, fvOption fiberDragSource): the drag
# law at each cell's air (1e-9), the duct's momentum balance (p_in - p_out) A = drag
# (1e-6), the mat's drag within 2 % of the law at the inlet velocity (the mesh's
# deficit at the mat's faces), below Kuwabara's mat law and falling against it and
# Davies' as alpha grows (checkFiberDuct.py); serial and cut across the mats on 2
# ranks. ~3 s serial, ~11 s on 2 ranks.
foreach(mode serial parallel)
  case_test(fiberDuct.${mode} fiberDuct ${mode} ${PYTHON3} ${CASES}/checkFiberDuct.py)
  set_tests_properties(case.fiberDuct.${mode} PROPERTIES TIMEOUT 300)
endforeach()
