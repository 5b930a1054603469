#include "evaluation/protocol.hpp"
