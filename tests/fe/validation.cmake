# Validation of the finite-element shell model against independent references: the references
# and helpers themselves (fast), then the model against them (slow ones labelled fe_validation;
# CI runs all).
growthuq_add_test(test_fe_references test_fe_vella_reference.cpp test_fe_validation_support.cpp)
