# Included by CMakeLists.txt (mj_cli_test, mj_stderr_width_test, MJ_OUT,
# MJ_BENCH_QUICK and the bench_quick fixture come from there).
# Issue 39's chart and progress reproductions, on the shipped example with its
# charts: progress is one line per stage (it was 99 scrolling lines); the
# chart script has a log slip axis (the peaks sat in the first 5-7 % of a
# linear one), legends by sigma_n with each curve's RMS, the uplift's
# residuals, and the misfit, verdict and values in the title.
function(mj_file_test name file regex)
  add_test(NAME "cli: ${name}" COMMAND ${CMAKE_COMMAND} -DFILE=${file} "-DEXPECT_OUTPUT=${regex}"
    -P ${CMAKE_CURRENT_SOURCE_DIR}/file_matches.cmake)
endfunction()
set(mj_charts ${MJ_OUT}/calibration_charts)
mj_cli_test("calibrate: progress by stage" 0
  "\ncalibrate: stage 1/3, direct rules[^\n]*\ncalibrate: stage 2/3, one set: [0-9]+ unknowns.*accepted\ncalibrate: params\\.toml, report\\.md, fit_\\*\\.csv and charts in[ \n].*calibration_charts/\n$"
  calibrate --data ${PROJECT_SOURCE_DIR}/calibration_data/synthetic_example --out ${mj_charts})
set_tests_properties("cli: calibrate: progress by stage" PROPERTIES FIXTURES_SETUP mj_charts)
mj_file_test("calibrate chart: log slip axis" ${mj_charts}/calibration.gp
  "set title \"Shear[^\"]*\"\nset xlabel \"slip \\[mm\\] \\(log\\)\"[^\n]*\n[^\n]*\nset logscale x\nplot \"fit_shear_sn0\\.1\\.csv\"")
mj_file_test("calibrate chart: legends by sigma_n with the RMS" ${mj_charts}/calibration.gp
  "title \"[^\"]*n = -0\\.5 MPa \\(RMS 0\\.[0-9]+\\)\"")
mj_file_test("calibrate chart: the uplift's residuals" ${mj_charts}/calibration.gp
  "set title \"Uplift residuals \\(fit - data\\)\"")
mj_file_test("calibrate chart: misfit and values in the title" ${mj_charts}/calibration.gp
  "title \"Calibration, one set: RMS misfit 0\\.0[0-9]+ of each curve's scale, accepted.nkn [0-9.]+, ks [0-9.]+")
set_tests_properties("cli: calibrate chart: log slip axis" "cli: calibrate chart: legends by sigma_n with the RMS"
  "cli: calibrate chart: the uplift's residuals" "cli: calibrate chart: misfit and values in the title"
  PROPERTIES FIXTURES_REQUIRED mj_charts)
# The bench charts (issue 39): the error axis ends at the data (it reached
# 1e4; the quick run's errors stay below 1e2), the keys stand beside the
# panels, drifted and failed cells are told apart.
mj_file_test("bench chart: error axis within the data" ${MJ_BENCH_QUICK}/work_precision_all.gp
  "set yrange \\[1e-[0-9]+:1e(\\+0[0-2]|-[0-9]+)\\]")
mj_file_test("bench chart: keys beside the panels" ${MJ_BENCH_QUICK}/work_precision_all.gp
  "set key at screen [0-9.]+,[0-9.]+ left top[^\n]*box opaque")
mj_file_test("bench chart: drifted and failed told apart" ${MJ_BENCH_QUICK}/stability_map.gp
  "title \"drifted \\(marked x\\)\".*title \"failed \\(marked o\\)\"")
set_tests_properties("cli: bench chart: error axis within the data" "cli: bench chart: keys beside the panels"
  "cli: bench chart: drifted and failed told apart" PROPERTIES FIXTURES_REQUIRED bench_quick)
# The progress lines within 100 columns too (stage 2's was 122).
mj_stderr_width_test("calibrate's progress on stderr" 0
  calibrate --data ${PROJECT_SOURCE_DIR}/calibration_data/synthetic_example --out ${MJ_OUT}/width_calibration_progress --no-plots)
# The validation charts (issue 39: Atkinson's cycles touched the frame): the
# x axis has margins on both sides.
set_tests_properties("cli: validate (all series, regression baselines)" PROPERTIES FIXTURES_SETUP mj_validation)
mj_file_test("validate chart: x margins on Atkinson's cycles" ${MJ_OUT}/validation/atkinson_cyclic_shear.gp
  "set offsets graph 0\\.0[1-9], graph 0\\.0[1-9], ")
set_tests_properties("cli: validate chart: x margins on Atkinson's cycles" PROPERTIES FIXTURES_REQUIRED mj_validation)
