// MotionOptions' one table: every option's name, doc, unit, default and range, which
// check_motion_options checks and the workbench reads (popupcore.MotionOptions.fields()). The
// view's own table is motion_view.cpp's.
#include "popup/motion/motion_types.hpp"

namespace popup {
namespace {

using Field = OptionField;

using MotionField = OptionRow<MotionOptions>;

const std::vector<MotionField>& own_fields()
{
    static const std::vector<MotionField> fields = [] {
        std::vector<MotionField> table = {
            {Field::number("motion_weight", "w_m of eq 6.5: how much following the paths counts")
                 .at_least(0)
                 .at_most(1e6),
             [](const MotionOptions& o) { return o.motion_weight; }},
            {Field::number("depth_weight", "w_d of eq 6.5: how much keeping the depth order counts")
                 .at_least(0)
                 .at_most(1e6),
             [](const MotionOptions& o) { return o.depth_weight; }},
            {Field::number("collision_weight", "w_c of eq 6.8: the cost of colliding parts")
                 .above(0),
             [](const MotionOptions& o) { return o.collision_weight; }},
            {Field::count("iterations", "annealing iterations per search chain")
                 .at_least(0)
                 .at_most(1e8),
             [](const MotionOptions& o) { return double(o.iterations); }},
            {Field::count("search_chains",
                          "independent annealing runs, one thread each, the best kept")
                 .at_least(1)
                 .at_most(16),
             [](const MotionOptions& o) { return double(o.search_chains); }},
            {Field::number("layer_height_max",
                           "h_max: the highest floating layer; <= 0: 25 mm on an A4 card, scaled "
                           "to the card",
                           "mm"),
             [](const MotionOptions& o) { return o.layer_height_max; }},
            {Field::count("seed", "random seed; same seed, same design").at_least(0).at_most(1e18),
             [](const MotionOptions& o) { return double(o.seed); }},
            {Field::on_off("outlines",
                           "moving and stationary patches take the character's outline"),
             [](const MotionOptions& o) { return double(o.outlines); }},
            // Checked against the chains found (design_from_targets): no range of its own.
            {Field::vector(OptionKind::names, "animate_only",
                           "the chains to animate, by name as the report gives them; the others "
                           "are held still; empty: all"),
             nullptr},
            {Field::number("prune_fraction",
                           "τp: a leaf chain lighter than this fraction of the mean is merged "
                           "into its parent")
                 .at_least(0)
                 .at_most(1)
                 .in("chains"),
             [](const MotionOptions& o) { return o.chains.prune_fraction; }},
            {Field::number("min_chain_size",
                           "a leaf chain reaching less than this fraction of the character's "
                           "size is part of the chain it hangs from (fingers, face bones), "
                           "unless such chains are all that moves; 0 keeps them")
                 .at_least(0)
                 .at_most(1)
                 .in("chains"),
             [](const MotionOptions& o) { return o.chains.min_chain_size; }},
        };
        return with_struct_defaults(table);
    }();
    return fields;
}

} // namespace

const std::vector<OptionField>& motion_option_fields()
{
    static const std::vector<OptionField> fields = [] {
        std::vector<OptionField> out, chains;
        for (const MotionField& f : own_fields())
            (f.field.group.empty() ? out : chains).push_back(f.field);
        for (const OptionField& f : motion_view_fields())
            out.push_back(f.in("view"));
        out.insert(out.end(), chains.begin(), chains.end());
        return out;
    }();
    return fields;
}

Diagnostics check_motion_options(const MotionOptions& o)
{
    Diagnostics errors;
    check_rows(errors, own_fields(), o, "MotionOptions", "ChainOptions");
    // Eq 6.5 needs some weight on the paths or on the depth order.
    if (o.motion_weight == 0 && o.depth_weight == 0)
        errors.push_back(Diagnostic::error(
            DiagnosticCode::bad_option,
            "MotionOptions.motion_weight and depth_weight are both 0; one must be > 0",
            about_parameter("motion_weight")));
    const Diagnostics view = check_motion_view(o.view);
    errors.insert(errors.end(), view.begin(), view.end());
    return errors;
}

} // namespace popup
