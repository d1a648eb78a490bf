#include "build_mechanism.hpp"

#include "motion_parameters.hpp"

namespace popup::motion {

namespace {

/// The report's row of a mechanism of `kind` with parameters `params`.
FittedMechanism row_of(MechanismKind kind, const MechanismParams& params, const std::string& name,
                       const std::string& host)
{
    FittedMechanism row;
    row.kind = kind;
    row.params = params;
    row.name = name;
    row.host = host;
    return row;
}

/// The report's row of a floating layer (the stationary mapping's, or an off-fold arm's host).
FittedMechanism layer_row(const FloatingLayerParams& f, const std::string& name,
                          const std::string& host)
{
    return row_of(MechanismKind::floating_layer, f, name, host);
}

} // namespace

Result<std::vector<MechanismParts>> build_mechanism(Scaffold& scaffold, const BasePatchPair& host,
                                                    const MotionMechanism& m,
                                                    const std::string& name,
                                                    std::vector<FittedMechanism>& rows)
{
    Result<std::vector<MechanismParts>> out;
    auto take = [&](Result<MechanismParts> r, FittedMechanism row) {
        out.diagnostics.insert(out.diagnostics.end(), r.diagnostics.begin(), r.diagnostics.end());
        if (!r.ok) {
            out.ok = false;
            return false;
        }
        out.value.push_back(r.value);
        rows.push_back(std::move(row));
        return true;
    };
    FittedMechanism row;
    row.name = name;
    row.host = "central fold";
    switch (m.kind()) {
    case MotionKind::rotation: {
        const RotationArmParams r = rotation_params(m);
        row = row_of(MechanismKind::rotation_arm, r, name, row.host);
        if (!rotation_off_fold(m)) {
            take(add_rotation_arm(scaffold, host, r, name), row);
            break;
        }
        // Off the fold: the floating layer first (the host before what it carries), then the
        // arm on its side pair (docs/MATH.md, A rotation arm on a floating layer's side).
        const FloatingLayerParams f = rotation_layer(m);
        const FittedMechanism layer = layer_row(f, name + "_layer", row.host);
        if (!take(add_floating_layer(scaffold, host, f, layer.name), layer))
            break;
        const BasePatchPair side =
            out.value.back().offered.at(rotation_side(m) == LayerSide::ground ? 1 : 2);
        row.host = side.name;
        take(add_rotation_arm(scaffold, side, r, name), row);
        break;
    }
    case MotionKind::vertical: {
        const VBoxFoldParams v = vertical_params(m);
        row = row_of(MechanismKind::vertical_translation, v, name, row.host);
        take(add_vertical_translation(scaffold, host, v, name), row);
        break;
    }
    case MotionKind::horizontal: {
        const HorizontalTranslationParams h = horizontal_params(m);
        row = row_of(MechanismKind::horizontal_translation, h, name, row.host);
        take(add_horizontal_translation(scaffold, host, h, name), row);
        break;
    }
    case MotionKind::diagonal: {
        const VFoldParams v = diagonal_v_fold(m);
        row = row_of(MechanismKind::v_fold, v, name, row.host);
        if (!take(add_v_fold(scaffold, host, v, name), row))
            break;
        const BasePatchPair wings = out.value.back().offered.at(0);
        const StepFoldParams s = diagonal_step(m);
        const FittedMechanism step =
            row_of(MechanismKind::step_fold, s, name + "_step", wings.name);
        take(add_step_fold(scaffold, wings, s, step.name), step);
        break;
    }
    case MotionKind::stationary: {
        const FloatingLayerParams f = layer_params(m);
        take(add_floating_layer(scaffold, host, f, name), layer_row(f, name, row.host));
        break;
    }
    }
    return out;
}

} // namespace popup::motion
