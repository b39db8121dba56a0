# seaflex.batch and `seaflex batch` (issue 20): pytest with Debian's python (python3-distributed,
# python3-pandas, python3-h5py); the package staged by the build, else the source tree's
set(SEAFLEX_BATCH_TEST_ENV
  "PYTHONPATH=${PROJECT_BINARY_DIR}/python:${PROJECT_SOURCE_DIR}/python"
  "SEAFLEX_EXECUTABLE=$<TARGET_FILE:seaflex>" "PYTHONDONTWRITEBYTECODE=1")
foreach(name test_batch test_batch_failures test_batch_input test_batch_cluster
             test_batch_summary test_batch_cases)
  add_test(NAME python_${name} COMMAND /usr/bin/python3 -m pytest -q -p no:cacheprovider
           ${CMAKE_CURRENT_LIST_DIR}/${name}.py)
  set_tests_properties(python_${name} PROPERTIES ENVIRONMENT "${SEAFLEX_BATCH_TEST_ENV}"
                       LABELS regression TIMEOUT 120)
endforeach()
# 24 serial runs, two batches of 24 cases and a killed worker: about 30 s
set_tests_properties(python_test_batch PROPERTIES LABELS "slow;regression")
