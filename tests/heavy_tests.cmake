# The heavy verification tests: refinement and step-halving studies, long implicit windows and
# whole hybrid scenes that take 25 s to 4 min each on 2 cores. CTest reads this file after each
# test directory's discovered tests (tests added by add_test take the label where they are
# added, as the coupling suite's full MPI runs do); `scripts/test` leaves the label `heavy` out and
# `scripts/test --heavy` runs everything. A name that no longer exists is ignored, so a renamed
# test falls back into the everyday suite rather than out of every run.
set(vulnus_heavy_tests
  # MPM verification studies
  Cpdi.HangingColumnHoldsTogetherAndSettlesNearTheAnalyticEquilibrium
  MpmTimeConvergence.WaterStiffPunchWoundAgreesAtHalfTheStep
  Locking.FarFieldShearModeKeepsItsPeriodWithFBar
  Locking.MpmShearModeKeepsItsPeriodWithCellAveragedVolume
  # implicit coupling windows: long dashpot windows, probing at full size, their restarts
  HybridWindowsProbed.LongDashpotWindowsThatTheFarFieldCannotTakeAreHalved
  HybridWindowsProbed.ProbedEffectiveMassMatchesTheExactOneAndBalancesAlike
  HybridWindowsRestart.ALongDashpotWindowSavedMidWayContinuesBitForBit
  AdaptiveZoneImplicit.ConvertedCellsLeaveANewmarkFarFieldThatKeepsTheMotion
  # the loaded interface's longest windows and the generalized-alpha restart (the shorter
  # Newmark windows, generalized alpha's and the Newmark restart stay in the everyday suite)
  Windows/HybridWindows.ExchangeMomentumExactlyOnALoadedInterface/newmark_50_shortened
  Windows/HybridWindows.ExchangeMomentumExactlyOnALoadedInterface/dashpot_500
  Integrators/HybridRestart.RestartedRunContinuesBitForBit/generalized_alpha
  # whole hybrid scenes
  HybridPaperScene.MatchesThePureMpmReferenceWithinFivePercent
  HybridPaperScene.AWoundReachingTheFarFieldStopsTheRunOrIsFlagged
  AdaptiveZoneRestart.KilledAfterAConversionContinuesBitForBit
  DistributedPaperScene.HybridOnOneTwoAndThreeRanksGivesTheSameWound
  DistributedPaperScene.HybridAtTheDefaultsStaysWithinTheRoundOffSpread)
foreach(test_name ${vulnus_heavy_tests})
  set_tests_properties(${test_name} PROPERTIES LABELS heavy)
endforeach()
