#include "core/identification/ParameterSet.h"

namespace hsmu {

ParameterBoundsMap tableIIIBounds()
{
    return {{"k0", {0.7, 1.4}},      {"alpha", {0.001, 0.05}},   {"n", {1.0, 3.0}},
            {"beta", {2.5, 5.0}},    {"gamma", {0.0, 2.5}},      {"deltaNu", {0.001, 0.1}},
            {"deltaEta", {0.001, 0.1}}};
}

} // namespace hsmu
