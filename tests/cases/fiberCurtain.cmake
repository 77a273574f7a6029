# A fiber curtain falling into still air, coupled both ways (tests/cases/fiberCurtain;
# included from CMakeLists.txt: CASES, RUN, PYTHON3, case_test). The fibers' drag every
# step: on the air = -(on the fibers - outside the mesh) to 1e-10; the fibers' momentum
# change = their drag and weight to 1e-10; the air's momentum change = the drag applied
# (one step late, semi-implicit) + the walls' force to 1e-6 (PISO, 4 correctors); the air
# falls in the curtain (checkFiberCurtain.py), serial and on 2 ranks (the curtain across
# the cut). The 2 ranks give the serial run's tables and fibers (1e-8; measured 4e-12),
# and a restart in the middle of the injection continues to the bit, serial and on 2 ranks.
foreach(mode serial parallel)
  case_test(fiberCurtain.${mode} fiberCurtain ${mode}
    ${PYTHON3} ${CASES}/checkFiberCurtain.py)
  set_tests_properties(case.fiberCurtain.${mode} PROPERTIES TIMEOUT 180
    FIXTURES_SETUP fiberCurtain.${mode})
endforeach()

set(CURTAIN_STATE 0.15625/uniform/dropletFiber/dropletFiber)
# Both ranks hold fibers (the union printed as 'processorN holds fibers [ids]')
add_test(NAME case.fiberCurtain.serialEqualsParallel
  COMMAND bash -c "set -o pipefail; '${PYTHON3}' '${CASES}/checkFiberCurtainSame.py' '${RUN}/fiberCurtain.serial' '${RUN}/fiberCurtain.parallel' 1e-8 && '${PYTHON3}' '${CASES}/compareFiberUnion.py' '${RUN}/fiberCurtain.serial/${CURTAIN_STATE}' '${RUN}/fiberCurtain.parallel' '${CURTAIN_STATE}' 1e-8 | tee /dev/stderr | grep -c -E '^processor[01] holds fibers \\[[0-9]' | grep -q 2")
set_tests_properties(case.fiberCurtain.serialEqualsParallel PROPERTIES LABELS "case" TIMEOUT 60
  FIXTURES_REQUIRED "fiberCurtain.serial;fiberCurtain.parallel")

add_test(NAME case.fiberCurtain.restart
  COMMAND ${CASES}/checkFiberCurtainRestart.sh ${CASES}/fiberCurtain
    ${RUN}/fiberCurtain.serial ${RUN}/fiberCurtain.restart)
set_tests_properties(case.fiberCurtain.restart PROPERTIES LABELS "case" TIMEOUT 180
  FIXTURES_REQUIRED fiberCurtain.serial)
add_test(NAME case.fiberCurtain.restart.parallel
  COMMAND ${CASES}/checkFiberCurtainRestart.sh ${CASES}/fiberCurtain
    ${RUN}/fiberCurtain.parallel ${RUN}/fiberCurtain.restart.parallel parallel)
set_tests_properties(case.fiberCurtain.restart.parallel PROPERTIES LABELS "case" TIMEOUT 180
  PROCESSORS 2 FIXTURES_REQUIRED fiberCurtain.parallel)

# coupled true without an active fvOption fiberDragSource (switched off, or no
# fvOptions): warned at the start and again at the end that the air feels nothing
add_test(NAME case.fiberCurtain.coupledWithoutSource
  COMMAND ${CASES}/checkCoupledWithoutSource.sh ${CASES}/fiberCurtain ${RUN}/coupledWithoutSource)
set_tests_properties(case.fiberCurtain.coupledWithoutSource PROPERTIES LABELS "case" TIMEOUT 300)

# The populations' drag spread over their kernels' cells (docs/model.md sec. 12, P56;
# collision.spread.maxClustering 0: the levels by the count, above the grid's own): the
# same budgets every step (the air gets exactly what the fibers lose), the log says how
# much was spread, and 2 ranks give the serial run's tables (1e-8)
foreach(mode serial parallel)
  add_test(NAME case.fiberCurtain.spreadDrag.${mode}
    COMMAND ${CASES}/runEdited.sh ${CASES}/fiberCurtain ${RUN}/fiberCurtain.spreadDrag.${mode} ${mode}
      "functions/dropletFiber/collision { spread { maxClustering 0; } }" --
      bash -c "'${PYTHON3}' '${CASES}/checkFiberCurtain.py' \"$0\" && grep -q 'of which spread with the weighted fibers. populations over their kernels. cells (-\\?[0-9]' \"$0\"/log.pimpleFoam")
  set_tests_properties(case.fiberCurtain.spreadDrag.${mode} PROPERTIES LABELS "case" TIMEOUT 180
    PROCESSORS $<IF:$<STREQUAL:${mode},serial>,1,2> FIXTURES_SETUP fiberCurtain.spreadDrag.${mode})
endforeach()
add_test(NAME case.fiberCurtain.spreadDrag.serialEqualsParallel
  COMMAND ${PYTHON3} ${CASES}/checkFiberCurtainSame.py ${RUN}/fiberCurtain.spreadDrag.serial
    ${RUN}/fiberCurtain.spreadDrag.parallel 1e-8)
set_tests_properties(case.fiberCurtain.spreadDrag.serialEqualsParallel PROPERTIES LABELS "case" TIMEOUT 60
  FIXTURES_REQUIRED "fiberCurtain.spreadDrag.serial;fiberCurtain.spreadDrag.parallel")
