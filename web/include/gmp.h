/* The web build's <gmp.h>: mini-gmp has every mpq_ call core/geometry/predicates.cpp makes. */
#pragma once
#include "mini-gmp.h"
#include "mini-mpq.h"
