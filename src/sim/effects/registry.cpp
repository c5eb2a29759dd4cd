// The one place that maps PF_FEATURE_* bits to effect classes.
#include "sim/effects/registry.h"

#include "sim/effects/force_fields/force_fields.h"
#include "sim/effects/obstacles/obstacles.h"

namespace pf {

std::unique_ptr<Effect> make_effect(uint32_t feature) {
    switch (feature) {
        case PF_FEATURE_FORCE_FIELDS: return std::make_unique<ForceFieldsEffect>();
        case PF_FEATURE_OBSTACLES: return std::make_unique<ObstaclesEffect>();
        default: return nullptr;
    }
}

}  // namespace pf
