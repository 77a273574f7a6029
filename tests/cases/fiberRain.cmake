# A uniform rain of straight fibers falling without air onto a belt moving at 0.256 m/s
# (tests/cases/fiberRain, fibers.laydown on the patch bottom; included from
# CMakeLists.txt: CASES, RUN, PYTHON3, case_test). Ten injectors, one per 10 mm column,
# at 10 k degrees to the belt's motion: every fiber is laid 69 steps after its birth
# step at a place worked out by hand, every cell of a complete row holds exactly 10
# fibers: G = mass flow / (W V) = 157.08 g/m2 (P48; deterministic, so to round-off,
# 1e-12; each fiber along its length over the rows it crosses, P58), the orientation
# order of column k cos(20 k deg), the map's totals the table's
# and the log's, glass and fiber-mass balances to round-off at every write time, the step
# table's laidGlass every step (checkFiberRain.py), serial and on 2 ranks (a checkerboard
# decomposition: every fiber is born on one processor and laid by the other). ~2 s a run.
foreach(mode serial parallel)
  case_test(fiberRain.${mode} fiberRain ${mode} ${PYTHON3} ${CASES}/checkFiberRain.py)
  set_tests_properties(case.fiberRain.${mode} PROPERTIES TIMEOUT 120
    FIXTURES_SETUP fiberRain.${mode})
endforeach()

# 2 ranks lay the serial run's mat: the table and the maps to the bit but the fibers'
# `across` (1e-15 m: the patch's centre summed in another order), the state's mat and the
# step table alike (its fiber mass in the air to 1e-13)
add_test(NAME case.fiberRain.serialEqualsParallel
  COMMAND ${PYTHON3} ${CASES}/checkFiberRainSame.py ${RUN}/fiberRain.serial ${RUN}/fiberRain.parallel)
set_tests_properties(case.fiberRain.serialEqualsParallel PROPERTIES LABELS "case" TIMEOUT 60
  FIXTURES_REQUIRED "fiberRain.serial;fiberRain.parallel")

# A restart at 0.25 s (470 fibers laid, 170 in the air) continues the mat: the new
# laydown.dat holds exactly the uninterrupted run's rows after 0.25, the step table, the
# maps, the state's mat and the log's figures at 0.375 and 0.5 are the uninterrupted run's
# to the bit; serial and on 2 ranks
add_test(NAME case.fiberRain.restart
  COMMAND ${CASES}/checkFiberRainRestart.sh ${CASES}/fiberRain
    ${RUN}/fiberRain.serial ${RUN}/fiberRain.restart)
set_tests_properties(case.fiberRain.restart PROPERTIES LABELS "case" TIMEOUT 120
  FIXTURES_REQUIRED fiberRain.serial)
add_test(NAME case.fiberRain.restart.parallel
  COMMAND ${CASES}/checkFiberRainRestart.sh ${CASES}/fiberRain
    ${RUN}/fiberRain.parallel ${RUN}/fiberRain.restart.parallel parallel)
set_tests_properties(case.fiberRain.restart.parallel PROPERTIES LABELS "case" TIMEOUT 120
  PROCESSORS 2 FIXTURES_REQUIRED fiberRain.parallel)

# A state written before the population counted the fibers the belt took (the laid
# totals in the mat's entry only; references/fiberRainState0.25.tar.xz, written by that
# version) restarts and continues to 0.5 as the uninterrupted run: the laid fibers, the
# step table and the log's balances to the bit; that version laid each fiber whole in its
# centre's cell, without error sums: warned, the maps the same glass and fibers (1e-12)
add_test(NAME case.fiberRain.olderState
  COMMAND ${CASES}/checkOldStateRestart.sh ${CASES}/fiberRain
    ${RUN}/fiberRain.serial ${RUN}/fiberRain.olderState
    ${CASES}/references/fiberRainState0.25.tar.xz)
set_tests_properties(case.fiberRain.olderState PROPERTIES LABELS "case" TIMEOUT 120
  FIXTURES_REQUIRED fiberRain.serial)

# Bad fibers.laydown entries (a patch not found or not planar, cell <= 0, a velocity out
# of the plane, patch with point and normal or with width, no belt, a key not known, a
# zero normal) stop at the start with a FatalIOError naming the entry; the same belt
# given as point, normal and width lays the hand's mat; with footprint centre every cell
# holds the fibers whose centres fall in it (the map before P58); with the populations spread (P59)
# the map's glass is the table's and every complete row the rain's G (1e-12)
add_test(NAME case.fiberRain.belt
  COMMAND ${CASES}/checkFiberRainBelt.sh ${CASES}/fiberRain ${RUN}/fiberRain.belt)
set_tests_properties(case.fiberRain.belt PROPERTIES LABELS "case" TIMEOUT 120)

# dropletFiberFormingLine on the rain's mat at 0.5 s (P60-P62, by hand): the hood's area
# weight G +- G/30 (900 computed fibers in the 9 complete rows), counting noise 0.1 and
# its own CoV 0; a line of 3: 3 G +- sqrt(3) G/30, noise 0.1/sqrt(3); profile.dat; -hoods
# 0 and a line longer than the complete rows stop naming the option
add_test(NAME case.fiberRain.formingLine
  COMMAND ${CASES}/checkFormingLine.sh ${RUN}/fiberRain.serial)
set_tests_properties(case.fiberRain.formingLine PROPERTIES LABELS "case" TIMEOUT 60
  FIXTURES_REQUIRED fiberRain.serial)
