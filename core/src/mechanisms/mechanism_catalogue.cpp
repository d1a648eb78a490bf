#include "popup/mechanisms/mechanism_catalogue.hpp"

#include <cctype>
#include <cmath>
#include <stdexcept>

namespace popup {
namespace {

constexpr double degree = M_PI / 180.0;
constexpr double largest = 2000.0; // mm: the bound of every mechanism's lengths in the generators

/// A field of params struct `Params` read and written through `member` (double, int or bool).
template <class Params, class T, class Owner>
ParameterField field(T Owner::*member, std::string name, std::string property, FieldUnit unit,
                     double default_value, double min, double max, HostBound bound,
                     std::string range, std::string doc)
{
    ParameterField f{std::move(name),
                     std::move(property),
                     unit,
                     default_value,
                     min,
                     max,
                     bound,
                     std::move(range),
                     std::move(doc),
                     {},
                     {}};
    f.get = [member](const MechanismParams& p) { return double(std::get<Params>(p).*member); };
    f.set = [member](MechanismParams& p, double value) {
        T& slot = std::get<Params>(p).*member;
        if constexpr (std::is_same_v<T, bool>)
            slot = value > 0.5;
        else if constexpr (std::is_same_v<T, int>)
            slot = int(std::lround(value));
        else
            slot = value;
    };
    return f;
}

/// Offset and Width, shared by every kind placed by an interval along its host's hinge.
template <class Params>
std::vector<ParameterField> placement(const std::string& what, double width = 40.0)
{
    return {field<Params>(&Params::offset, "offset", "Offset", FieldUnit::length, 20.0, 0, largest,
                          HostBound::along_hinge, ">= 0 mm and Offset + Width <= the host's length",
                          "Start of " + what + " along the host's hinge"),
            field<Params>(&Params::width, "width", "Width", FieldUnit::length, width, 0, largest,
                          HostBound::along_hinge, "> 0 mm and <= the host's length",
                          "Extent of " + what + " along the host's hinge")};
}

template <class Params, class Add> MechanismGenerator generator(Add add)
{
    return [add](Scaffold& s, const BasePatchPair& host, const MechanismParams& p,
                 const std::string& name) { return add(s, host, std::get<Params>(p), name); };
}

std::vector<ParameterField> with(std::vector<ParameterField> head, std::vector<ParameterField> tail)
{
    head.insert(head.end(), tail.begin(), tail.end());
    return head;
}

// The parts a box fold and a floating layer share (both are the library's parallel box).
std::vector<PartTitle> box_parts(const std::string& walls, const std::string& top)
{
    return {{"C", "centre " + walls.substr(0, walls.find(','))},
            {"L", walls + ", ground side"},
            {"R", walls + ", backdrop side"},
            {"TG", top + ", ground side"},
            {"TB", top + ", backdrop side"},
            {"FL", "front end, ground side"},
            {"FR", "front end, backdrop side"},
            {"BL", "back end, ground side"},
            {"BR", "back end, backdrop side"}};
}

CatalogueEntry tent_fold()
{
    using P = TentFoldParams;
    return {MechanismKind::tent_fold,
            "tent_fold",
            "TentFold",
            "Tent fold",
            "TentFoldParams",
            "T",
            false,
            with(placement<P>("the tent"),
                 {field<P>(&P::foot, "foot", "Foot", FieldUnit::length, 20.0, 0, largest,
                           HostBound::ground_depth, "> 0 mm and < the depth of the host's ground",
                           "Distance of the ground slope's foot from the hinge"),
                  field<P>(&P::foot_backdrop, "foot_backdrop", "FootBackdrop", FieldUnit::length,
                           20.0, 0, largest, HostBound::backdrop_depth,
                           "> 0 mm and < the depth of the host's backdrop",
                           "Distance of the backdrop slope's foot from the hinge"),
                  field<P>(&P::slope, "slope", "Slope", FieldUnit::length, 30.0, 0, largest,
                           HostBound::none,
                           "long enough for both slopes to reach the apex, and <= 2000 mm",
                           "Length of the ground-side slope")}),
            {},
            {{"slope_ground", "slope, ground side"}, {"slope_backdrop", "slope, backdrop side"}},
            P{},
            generator<P>(&add_tent_fold)};
}

CatalogueEntry step_fold()
{
    using P = StepFoldParams;
    return {MechanismKind::step_fold,
            "step_fold",
            "StepFold",
            "Step fold",
            "StepFoldParams",
            "S",
            false,
            with(placement<P>("the step"),
                 {field<P>(&P::run_ground, "run_ground", "RunGround", FieldUnit::length, 30.0, 0,
                           largest, HostBound::ground_depth,
                           "> 0 mm and < the depth of the host's ground",
                           "Distance of the riser's fold on the host's ground from the hinge (= "
                           "tread depth)"),
                  field<P>(&P::run_backdrop, "run_backdrop", "RunBackdrop", FieldUnit::length, 20.0,
                           0, largest, HostBound::backdrop_depth,
                           "> 0 mm and < the depth of the host's backdrop",
                           "Distance of the tread's fold on the host's backdrop from the hinge (= "
                           "riser height)")}),
            {},
            {{"riser", "riser"}, {"tread", "tread"}},
            P{},
            generator<P>(&add_step_fold)};
}

CatalogueEntry v_fold()
{
    using P = VFoldParams;
    return {MechanismKind::v_fold,
            "v_fold",
            "VFold",
            "V-fold",
            "VFoldParams",
            "V",
            false,
            {field<P>(&P::offset, "offset", "Offset", FieldUnit::length, 20.0, 0, largest,
                      HostBound::along_hinge, ">= 0 mm, the v within the host's length",
                      "Point O of the v along the host's hinge"),
             field<P>(&P::run, "run", "Run", FieldUnit::length, 40.0, 0, largest, HostBound::none,
                      "> 0 mm, Run·sin(HingeAngle) < the host's depth",
                      "Length of each wing's fold on the host, |OA| = |OB|"),
             field<P>(&P::hinge_angle, "hinge_angle", "HingeAngle", FieldUnit::angle, 45 * degree,
                      0, 90 * degree, HostBound::none, "> 0° and < 90°",
                      "Angle between each wing's fold on the host and the host's hinge"),
             field<P>(&P::spine, "spine", "Spine", FieldUnit::length, 45.0, 0, largest,
                      HostBound::none, "> 0 mm and <= the host's largest extent",
                      "Length of the spine O-P at the design state"),
             field<P>(&P::spine_angle, "spine_angle", "SpineAngle", FieldUnit::angle, 60 * degree,
                      0, 180 * degree, HostBound::none, "> 0° and < 180°",
                      "Angle of the spine above the host's hinge at the design state")},
            {"wings"}, // a step fold on the wings makes the diagonal translation (§4.3.3)
            {{"wing_ground", "wing, ground side"}, {"wing_backdrop", "wing, backdrop side"}},
            P{},
            generator<P>(&add_v_fold)};
}

CatalogueEntry box_fold()
{
    using P = BoxFoldParams;
    return {
        MechanismKind::box_fold,
        "box_fold",
        "BoxFold",
        "Box fold",
        "BoxFoldParams",
        "B",
        false,
        with(placement<P>("the box"),
             {field<P>(&P::depth_ground, "depth_ground", "DepthGround", FieldUnit::length, 30.0, 0,
                       largest, HostBound::ground_depth,
                       "> 0 mm and <= the depth of the host's ground",
                       "Depth of the box on the host's ground side (= its top's ground half)"),
              field<P>(&P::depth_backdrop, "depth_backdrop", "DepthBackdrop", FieldUnit::length,
                       30.0, 0, largest, HostBound::backdrop_depth,
                       "> 0 mm and <= the depth of the host's backdrop",
                       "Depth of the box on the host's backdrop side (= its top's backdrop half)"),
              field<P>(&P::height, "height", "Height", FieldUnit::length, 30.0, 0, largest,
                       HostBound::none, "> 0 and <= 2000 mm",
                       "Height of the box's top over the hinge"),
              field<P>(&P::front, "front", "Front", FieldUnit::flag, 1, 0, 1, HostBound::none,
                       "yes or no", "Front panels (without front and back the box shears)"),
              field<P>(&P::back, "back", "Back", FieldUnit::flag, 1, 0, 1, HostBound::none,
                       "yes or no", "Back panels"),
              field<P>(&P::panel_pairs, "panel_pairs", "PanelPairs", FieldUnit::count, 1, 1, 10,
                       HostBound::none, "1 to 10",
                       "Front and back panel pairs per end, strips stacked up the end")}),
        {"top", "side_ground", "side_backdrop"},
        box_parts("wall", "top"),
        P{},
        generator<P>(&add_box_fold)};
}

/// The v-box's walls and top; a vertical translation is its front half.
std::vector<ParameterField> v_box_fields(const std::string& height_doc, const std::string& angle)
{
    using P = VBoxFoldParams;
    return {field<P>(&P::offset, "offset", "Offset", FieldUnit::length, 20.0, 0, largest,
                     HostBound::along_hinge, ">= 0 mm, the v-box within the host's length",
                     "Front corner along the host's hinge"),
            field<P>(&P::side, "side", "Side", FieldUnit::length, 40.0, 0, largest, HostBound::none,
                     "> 0 mm, Side·sin(WallAngle) < the host's depth and 2·Side·cos(WallAngle) <= "
                     "its length",
                     "Length of each wall along the host"),
            field<P>(&P::height, "height", "Height", FieldUnit::length, 30.0, 0, largest,
                     HostBound::none, "> 0 and <= 2000 mm", height_doc),
            field<P>(&P::wall_angle, "wall_angle", "WallAngle", FieldUnit::angle, 45 * degree, 0,
                     90 * degree, HostBound::none, "> 0° and < 90°",
                     "Angle " + angle + "between each wall and the host's hinge")};
}

std::vector<PartTitle> v_box_parts(bool back)
{
    std::vector<PartTitle> parts{{"FL", "front wall, ground side"},
                                 {"FR", "front wall, backdrop side"},
                                 {"TG", "top, ground side"},
                                 {"TB", "top, backdrop side"}};
    if (back)
        parts.insert(parts.end(),
                     {{"BL", "back wall, ground side"}, {"BR", "back wall, backdrop side"}});
    return parts;
}

CatalogueEntry v_box_fold()
{
    return {MechanismKind::v_box_fold,
            "v_box_fold",
            "VBoxFold",
            "V-box",
            "VBoxFoldParams",
            "X",
            false,
            v_box_fields("Height of the walls at the design state", ""),
            {},
            v_box_parts(true),
            VBoxFoldParams{},
            generator<VBoxFoldParams>(&add_v_box_fold)};
}

CatalogueEntry rotation_arm()
{
    using P = RotationArmParams;
    return {MechanismKind::rotation_arm,
            "rotation_arm",
            "RotationArm",
            "Rotation arm",
            "RotationArmParams",
            "R",
            true,
            {field<P>(&P::offset, "offset", "Offset", FieldUnit::length, 20.0, 0, largest,
                      HostBound::along_hinge, ">= 0 mm and Offset + Spine <= the host's length",
                      "Point O along the host's hinge"),
             field<P>(&P::spine, "spine", "Spine", FieldUnit::length, 40.0, 0, largest,
                      HostBound::along_hinge, "> 0 mm and <= the host's length",
                      "Length l of the spine O-R along the hinge"),
             field<P>(&P::run, "run", "Run", FieldUnit::length, 30.0, 0, largest, HostBound::none,
                      "> 0 mm and < the depth of the host's ground and backdrop",
                      "Reach w of the wings from the hinge"),
             field<P>(&P::arm, "arm", "Arm", FieldUnit::length, 20.0, 0, largest,
                      HostBound::backdrop_depth,
                      "> 0 mm and <= Spine²/Run and the depth of the host's backdrop",
                      "Length h of the arm past the spine (<= l²/w)")},
            {},
            {{"wing_arm", "wing with the arm"}, {"wing_backdrop", "wing, backdrop side"}},
            P{},
            generator<P>(&add_rotation_arm)};
}

CatalogueEntry horizontal_translation()
{
    using P = HorizontalTranslationParams;
    return {
        MechanismKind::horizontal_translation,
        "horizontal_translation",
        "HorizontalTranslation",
        "Horizontal translation",
        "HorizontalTranslationParams",
        "H",
        true,
        {field<P>(&P::offset, "offset", "Offset", FieldUnit::length, 20.0, 0, largest,
                  HostBound::along_hinge, ">= 0 mm and Offset + Width <= the host's length",
                  "Start along the host's hinge"),
         field<P>(&P::width, "width", "Width", FieldUnit::length, 40.0, 0, largest,
                  HostBound::along_hinge, "> 0 mm and <= the host's length",
                  "Extent along the host's hinge"),
         field<P>(&P::run_ground, "run_ground", "RunGround", FieldUnit::length, 40.0, 0, largest,
                  HostBound::ground_depth, "> 0 mm and < the depth of the host's ground",
                  "Step's riser foot from the hinge"),
         field<P>(&P::run_backdrop, "run_backdrop", "RunBackdrop", FieldUnit::length, 20.0, 0,
                  largest, HostBound::none, "> 0 mm and < RunGround",
                  "Step's tread foot, < RunGround"),
         field<P>(&P::reach, "reach", "Reach", FieldUnit::length, 60.0, 0, largest,
                  HostBound::ground_depth,
                  "> RunGround - RunBackdrop and <= the depth of the host's ground",
                  "Length r of M from the hinge to its end P")},
        {},
        {{"riser", "riser"}, {"tread", "tread"}, {"M", "sliding panel"}},
        P{},
        generator<P>(&add_horizontal_translation)};
}

CatalogueEntry vertical_translation()
{
    VBoxFoldParams half;
    half.back = false; // the generator builds the triangular half whatever `back` says
    return {MechanismKind::vertical_translation,
            "vertical_translation",
            "VerticalTranslation",
            "Vertical translation",
            "VBoxFoldParams",
            "Y",
            true,
            v_box_fields("Height h of the walls at the design state", "α "),
            {},
            v_box_parts(false),
            half,
            generator<VBoxFoldParams>(&add_vertical_translation),
            {{"back", 0.0}}};
}

CatalogueEntry floating_layer()
{
    using P = FloatingLayerParams;
    return {
        MechanismKind::floating_layer,
        "floating_layer",
        "FloatingLayer",
        "Floating layer",
        "FloatingLayerParams",
        "F",
        false,
        with(placement<P>("the layer"),
             {field<P>(&P::height, "height", "Height", FieldUnit::length, 25.0, 0, largest,
                       HostBound::none, "> 0 and <= 2000 mm",
                       "Height of the platform over the host"),
              field<P>(&P::support, "support", "Support", FieldUnit::length, 20.0, 0, largest,
                       HostBound::ground_depth, "> 0 mm and < the host's depth",
                       "Distance of each support from the hinge"),
              field<P>(&P::overhang, "overhang", "Overhang", FieldUnit::length, 15.0, 0, largest,
                       HostBound::none, ">= 0 and <= 2000 mm", "Platform beyond each support")}),
        {"top", "side_ground", "side_backdrop"}, // the platform and both supports
        box_parts("support", "platform"),
        P{},
        generator<P>(&add_floating_layer)};
}

} // namespace

const ParameterField* CatalogueEntry::field(const std::string& field_name) const
{
    for (const ParameterField& f : fields)
        if (f.name == field_name)
            return &f;
    return nullptr;
}

const std::vector<CatalogueEntry>& mechanism_catalogue()
{
    static const std::vector<CatalogueEntry> catalogue{tent_fold(),
                                                       step_fold(),
                                                       v_fold(),
                                                       box_fold(),
                                                       v_box_fold(),
                                                       rotation_arm(),
                                                       horizontal_translation(),
                                                       vertical_translation(),
                                                       floating_layer()};
    return catalogue;
}

const CatalogueEntry& catalogue_entry(MechanismKind kind)
{
    return mechanism_catalogue().at(size_t(kind));
}

const CatalogueEntry* find_kind(const std::string& name)
{
    for (const CatalogueEntry& e : mechanism_catalogue())
        if (e.name == name)
            return &e;
    return nullptr;
}

std::string part_title(MechanismKind kind, const std::string& code)
{
    const std::vector<PartTitle>& parts = catalogue_entry(kind).parts;
    for (const PartTitle& p : parts)
        if (p.code == code)
            return p.title;
    // An end of several panel pairs numbers its strips from the hinge up: FL1, FL2...
    size_t digits = code.size();
    while (digits > 0 && std::isdigit(static_cast<unsigned char>(code[digits - 1])))
        --digits;
    if (digits > 0 && digits < code.size())
        for (const PartTitle& p : parts)
            if (p.code == code.substr(0, digits))
                return p.title + ", strip " + code.substr(digits);
    return code;
}

const std::vector<PartTitle>& card_part_titles()
{
    static const std::vector<PartTitle> titles{{"ground", "ground page"},
                                               {"backdrop", "backdrop page"}};
    return titles;
}

} // namespace popup
