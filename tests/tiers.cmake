# The tiers of the test suite: every CTest test carries exactly one of three labels.
#
#   unit         the library's own tests (tests/<folder> of the library, the fuzz replays): a few
#                seconds each; `ctest --test-dir build -L unit -j2` takes under 2 minutes on 2 cores
#   integration  what runs a whole program or an outside tool: the command (tests/cli), the
#                examples (tests/examples_*), the browser page (tests/viewer), the JSON Schemas, the
#                generated docs, the installed package, the Python module (python/tests)
#   slow         any test that takes more than about 10 s on 2 cores, whatever its kind (the
#                long solves, the package build), the paper's degree tables, and the runs that
#                only contrast a switch on and off
#
#   ctest --test-dir build -L unit -j2          # the inner loop
#   ctest --test-dir build -LE slow -j2         # unit and integration
#   ctest --test-dir build -j2                  # everything (scripts/test.sh)
#
# A test program's tests take its folder's tier (integration for the folders listed below, unit
# otherwise), except those its slow filter names. A slow filter is a GoogleTest filter
# (`Suite.Name:Suite.Other*`); the test program is then listed twice, once without those tests and
# once with them only, so a test renamed out of the filter falls back to its folder's tier. The
# times beside each name are the ones that put it there (Release, BPDE_NATIVE=ON, shared libraries,
# `ctest -j2` on 2 cores).

set(BPDE_INTEGRATION_TEST_FOLDERS cli viewer examples_c1 examples_cmc examples_complex)

# The slow tests of each test program, with the seconds one `ctest -j2` took for each. Those marked
# "switch" solve one problem twice, a switch on and off, and compare: they measure the switch.
string(JOIN ":" BPDE_SLOW_TESTS_cmc
  CmcArea.VolumeFormReachesTheLargerCapByContinuationInV               # 111 s
  ComplexCmcCap.AreaSolveOnTheFanAtDegree6ReachesTheSphere             #  10 s, the polished fan at n = 6
  CmcArea.MeanCurvatureStartEndIsKeptWhenItIsTheLowerNumericalLimit    #  51 s
  CmcArea.RuleIsChosenAgainWhereTheStartNearlyFolds                    #  34 s
  CmcArea.TrustRegionPartConvergesWhereTheSoftModeLoopStops            #  three area solves, n = 4, 6, 10
  CmcArea.VolumeFormReturnsTheCapAndItsH                               #  29 s
  CmcArea.VolumeFormReachesTheLargerCapOffTheOrigin                    #  20 s
  CmcArea.CircleInThreeArcsAtHMinus09                                  #  18 s
  CmcArea.AgreesWithDirichletOnConformalData                           #  13 s
  CmcMeanCurvature.VolumeFormReachesTheLargerCapByContinuationInV      #  13 s (54 s on a busy machine)
  CmcArea.NumericalLimitFromTheDirichletPointTriesTheMinimalSurfaceBranch  # 10 s
  CmcArea.MeanCurvatureStartGoesOnAfterItsIterations                   #  10 s
  CmcArea.SpherePatchAtDegree8EndsAsANumericalLimitOnARegularSurface   #  10 s, switch
  CmcArea.MeanCurvatureStartGivesWayAndRestoresWhatItChanged           #   9 s, switch
  CmcArea.MeanCurvatureStartIsNotTriedOnConformalData                  #   7 s (12 s on a busy machine)
  CmcMeanCurvature.RuleCheckKeepsTheParametrisationRegularOnConformalData  # 7 s (36 s on a busy machine)
  CmcArea.MeanCurvatureStartLandsNearerTheSphere                       #   5 s, switch
)
string(JOIN ":" BPDE_SLOW_TESTS_pde
  PdeAccuracy.Table                                                    #   7 s, the paper's degree table
)
string(JOIN ":" BPDE_SLOW_TESTS_examples_complex
  ExamplesComplex.RectangleByTheAreaFunctional                        #  26 s, the area solve at degree 6
  ExamplesComplex.EnneperAtDegree10ReachesTheAreaTo1e10               #  45-60 s, the area solve at degree 10
)
string(JOIN ":" BPDE_SLOW_TESTS_cli
  Cli.CmcMeanCurvatureJob                                              #  25 s
  HostileInput.SizeLimitsHoldAtTheLimitAndRefuseOnePastIt              #  11 s
)

# Tests registered with add_test (not GoogleTest): regular expressions over their names.
set(BPDE_INTEGRATION_TESTS "^(Schema|Docs|Package|Python)\\.")
set(BPDE_SLOW_TESTS "^Package\\.consumer$")                           # 15 s with a warm compiler cache

# bpde_discover_tests(<test program> <folder of tests/>): gtest_discover_tests with the labels.
# Discovery runs when CTest starts (PRE_TEST), so that a change of tier needs no relink.
function(bpde_discover_tests target folder)
  if(folder IN_LIST BPDE_INTEGRATION_TEST_FOLDERS)
    set(tier integration)
  else()
    set(tier unit)
  endif()
  set(common DISCOVERY_MODE PRE_TEST DISCOVERY_TIMEOUT 60)
  if(DEFINED BPDE_SLOW_TESTS_${folder})
    gtest_discover_tests(${target} ${common} TEST_FILTER "-${BPDE_SLOW_TESTS_${folder}}"
                         PROPERTIES TIMEOUT 600 LABELS ${tier})
    gtest_discover_tests(${target} ${common} TEST_FILTER "${BPDE_SLOW_TESTS_${folder}}"
                         PROPERTIES TIMEOUT 600 LABELS slow)
  else()
    gtest_discover_tests(${target} ${common} PROPERTIES TIMEOUT 600 LABELS ${tier})
  endif()
endfunction()

# bpde_label_tests(): labels every add_test test of the calling directory (called once, at the
# end of each CMakeLists.txt that adds tests).
function(bpde_label_tests)
  get_property(tests DIRECTORY PROPERTY TESTS)
  foreach(test ${tests})
    if(test MATCHES "${BPDE_SLOW_TESTS}")
      set(tier slow)
    elseif(test MATCHES "${BPDE_INTEGRATION_TESTS}")
      set(tier integration)
    else()
      set(tier unit)
    endif()
    set_tests_properties(${test} PROPERTIES LABELS ${tier})
  endforeach()
endfunction()
