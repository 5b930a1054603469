#include "evaluation/metrics.hpp"
