# Validation of the finite-element shell model against independent references: the references
# and helpers themselves (fast), then the model against them (slow ones labelled fe_validation;
# CI runs all).
growthuq_add_test(test_fe_references test_fe_vella_reference.cpp test_fe_validation_support.cpp)
# The model against the references (each a few minutes at most on one core in release).
growthuq_add_test(test_fe_vella test_fe_vella.cpp)
set_tests_properties(test_fe_vella PROPERTIES LABELS fe_validation)
growthuq_test_timeout(test_fe_vella 600)
growthuq_add_test(test_fe_benchmarks test_fe_benchmarks.cpp)
set_tests_properties(test_fe_benchmarks PROPERTIES LABELS fe_validation)
growthuq_test_timeout(test_fe_benchmarks 900)
growthuq_add_test(test_fe_balance test_fe_balance.cpp)
set_tests_properties(test_fe_balance PROPERTIES LABELS fe_validation)
growthuq_test_timeout(test_fe_balance 900)
growthuq_add_test(test_fe_convergence test_fe_convergence.cpp)
set_tests_properties(test_fe_convergence PROPERTIES LABELS fe_validation)
growthuq_test_timeout(test_fe_convergence 1800)
growthuq_add_test(test_fe_envelope test_fe_envelope.cpp)
set_tests_properties(test_fe_envelope PROPERTIES LABELS fe_validation)
growthuq_test_timeout(test_fe_envelope 1800)
