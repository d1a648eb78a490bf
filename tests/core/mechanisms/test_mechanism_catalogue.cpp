// The catalogue against the generators it names: each row's defaults build on an A4 card, offer
// the pairs the row lists and make only parts the row titles; fields read and write the struct
// member they name.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "popup/mechanisms/designed_mechanism.hpp"
#include "popup/model/card.hpp"

using namespace popup;

namespace {

/// A mechanism of `kind` with every field at the catalogue's default (what a maker's new
/// feature gets), named after its feature.
DesignedMechanism with_maker_defaults(MechanismKind kind)
{
    const CatalogueEntry& entry = catalogue_entry(kind);
    DesignedMechanism m = DesignedMechanism::of_kind(kind, entry.feature, "central fold");
    for (const ParameterField& f : entry.fields)
        m.set_value(f.name, f.default_value);
    return m;
}

Scaffold a4_card()
{
    CardParams card;
    card.width = 210;
    card.depth = 148;
    return make_card(card).value;
}

} // namespace

TEST(MechanismCatalogue, RowsComeInKindOrderWithDistinctNames)
{
    const std::vector<CatalogueEntry>& rows = mechanism_catalogue();
    ASSERT_EQ(rows.size(), 9u);
    std::set<std::string> names, features, short_names;
    for (size_t k = 0; k < rows.size(); ++k) {
        EXPECT_EQ(size_t(rows[k].kind), k);
        EXPECT_EQ(find_kind(rows[k].name), &rows[k]);
        names.insert(rows[k].name);
        features.insert(rows[k].feature);
        short_names.insert(rows[k].short_name);
        for (const ParameterField& f : rows[k].fields) {
            EXPECT_LE(f.min, f.default_value) << rows[k].name << "." << f.name;
            EXPECT_LE(f.default_value, f.max) << rows[k].name << "." << f.name;
            EXPECT_FALSE(f.range.empty() || f.doc.empty()) << rows[k].name << "." << f.name;
        }
    }
    EXPECT_EQ(names.size(), 9u);
    EXPECT_EQ(features.size(), 9u);
    EXPECT_EQ(short_names.size(), 9u);
    EXPECT_EQ(find_kind("no_such_fold"), nullptr);
}

TEST(MechanismCatalogue, EveryKindBuildsItsDefaultsAndOffersWhatItsRowSays)
{
    for (const CatalogueEntry& entry : mechanism_catalogue()) {
        Scaffold s = a4_card();
        const size_t before = s.patches.size();
        DesignedMechanism m = with_maker_defaults(entry.kind);
        if (entry.kind == MechanismKind::box_fold)
            m.set_value("panel_pairs", 2); // strips FL1, FL2...
        const Result<MechanismParts> built = add_mechanism(s, central_fold(s), m);
        ASSERT_TRUE(built.ok) << entry.name << ": "
                              << (built.diagnostics.empty() ? "" : built.diagnostics[0].message);
        std::vector<std::string> offered;
        for (const BasePatchPair& pair : built.value.offered)
            offered.push_back(pair.name);
        std::vector<std::string> expected;
        for (const std::string& part : entry.offers)
            expected.push_back(entry.feature + "." + part);
        EXPECT_EQ(offered, expected) << entry.name;
        for (size_t i = before; i < s.patches.size(); ++i) {
            const std::string& name = s.patches[i].name;
            const std::string code = name.substr(name.find('.') + 1);
            const bool listed = std::any_of(entry.parts.begin(), entry.parts.end(),
                                            [&](const PartTitle& t) { return t.code == code; });
            EXPECT_TRUE(listed || part_title(entry.kind, code) != code)
                << name << " has no maker title";
        }
    }
}

TEST(MechanismCatalogue, FieldsReadAndWriteTheMemberTheyName)
{
    DesignedMechanism box = DesignedMechanism::of_kind(MechanismKind::box_fold, "B1");
    box.set_value("depth_backdrop", 12.5);
    box.set_value("panel_pairs", 3.4); // a count rounds
    box.set_value("front", 0.0);       // a flag is 0 or 1
    EXPECT_EQ(box.as<BoxFoldParams>().depth_backdrop, 12.5);
    EXPECT_EQ(box.as<BoxFoldParams>().panel_pairs, 3);
    EXPECT_FALSE(box.as<BoxFoldParams>().front);
    EXPECT_EQ(box.value("panel_pairs"), 3.0);
    EXPECT_EQ(box.parameter_values().size(),
              catalogue_entry(MechanismKind::box_fold).fields.size());
    EXPECT_THROW(box.value("spine"), std::out_of_range);
    // v-fold: no width; its extent along the hinge is the spine's run, spine·cos(spine angle).
    DesignedMechanism v = DesignedMechanism::of_kind(MechanismKind::v_fold, "V1");
    v.set_value("spine", 50);
    v.set_value("spine_angle", std::atan2(30.0, 40.0));
    EXPECT_NEAR(v.extent(), 40.0, 1e-12);
    EXPECT_EQ(catalogue_entry(MechanismKind::v_fold).field("width"), nullptr);
}

TEST(MechanismCatalogue, AVerticalTranslationIsTheVBoxHalfWhateverBackSays)
{
    const CatalogueEntry& entry = catalogue_entry(MechanismKind::vertical_translation);
    EXPECT_EQ(entry.field("back"), nullptr);
    EXPECT_EQ(entry.fixed, (std::vector<std::pair<std::string, double>>{{"back", 0.0}}));
    EXPECT_FALSE(std::get<VBoxFoldParams>(entry.defaults).back);
    EXPECT_EQ(entry.parts.size(), 4u); // FL, FR, TG, TB: no back walls
}

TEST(MechanismCatalogue, ParamsOfAnotherKindAreANamedError)
{
    Scaffold s = a4_card();
    DesignedMechanism m = DesignedMechanism::of_kind(MechanismKind::tent_fold, "T1");
    m.params = BoxFoldParams{};
    const Result<MechanismParts> r = add_mechanism(s, central_fold(s), m);
    ASSERT_FALSE(r.ok);
    EXPECT_EQ(r.diagnostics[0].code, DiagnosticCode::bad_parameter);
    EXPECT_NE(r.diagnostics[0].message.find("T1: a Tent fold needs TentFoldParams"),
              std::string::npos)
        << r.diagnostics[0].message;
    EXPECT_EQ(s.patches.size(), a4_card().patches.size()); // nothing added
}

TEST(MechanismCatalogue, PartTitlesNameStripsAndLeaveUnknownCodes)
{
    EXPECT_EQ(part_title(MechanismKind::box_fold, "TG"), "top, ground side");
    EXPECT_EQ(part_title(MechanismKind::box_fold, "FL2"), "front end, ground side, strip 2");
    EXPECT_EQ(part_title(MechanismKind::floating_layer, "C"), "centre support");
    EXPECT_EQ(part_title(MechanismKind::tent_fold, "XY7"), "XY7");
    EXPECT_EQ(part_title(MechanismKind::box_fold, "12"), "12");
}

TEST(PatchSubject, NamesAPatchByIdAndName)
{
    Patch p;
    p.id = 5;
    EXPECT_EQ(patch_subject(p), "patch 5");
    p.name = "BoxFold.TG";
    EXPECT_EQ(patch_subject(p), "patch 5 (BoxFold.TG)");
}
