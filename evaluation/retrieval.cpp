#include "evaluation/retrieval.hpp"
