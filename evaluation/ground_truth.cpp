#include "evaluation/ground_truth.hpp"
