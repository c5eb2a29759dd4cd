// The one place that maps PF_FEATURE_* bits to effect classes.
#include "sim/effects/registry.h"

#include "sim/effects/domain_motion/domain_motion.h"
#include "sim/effects/emitters/emitters.h"
#include "sim/effects/force_fields/force_fields.h"
#include "sim/effects/obstacles/obstacles.h"
#include "sim/effects/sinks/sinks.h"
#include "sim/effects/surface_tension/surface_tension.h"
#include "sim/effects/viscosity/viscosity.h"
#include "sim/effects/vorticity_confinement/vorticity_confinement.h"
#include "sim/effects/whitewater/whitewater.h"

namespace pf {

std::unique_ptr<Effect> make_effect(uint32_t feature, const pf_sim_desc& desc) {
    switch (feature) {
        case PF_FEATURE_FORCE_FIELDS: return std::make_unique<ForceFieldsEffect>();
        case PF_FEATURE_OBSTACLES: return std::make_unique<ObstaclesEffect>();
        case PF_FEATURE_EMITTERS: return std::make_unique<EmittersEffect>(desc);
        case PF_FEATURE_SINKS: return std::make_unique<SinksEffect>(desc);
        case PF_FEATURE_DOMAIN_MOTION: return std::make_unique<DomainMotionEffect>(desc);
        case PF_FEATURE_VORTICITY_CONFINEMENT: return std::make_unique<VorticityConfinementEffect>(desc);
        case PF_FEATURE_WHITEWATER: return std::make_unique<WhitewaterEffect>(desc);
        case PF_FEATURE_VISCOSITY: return std::make_unique<ViscosityEffect>(desc);
        case PF_FEATURE_SURFACE_TENSION: return std::make_unique<SurfaceTensionEffect>(desc);
        default: return nullptr;
    }
}

}  // namespace pf
