#pragma once
// The designs the validity tests, the sample files and the bindings tests share.
#include "popup/model/scaffold.hpp"

namespace popup::fixtures {

Scaffold valid_tent_card();  ///< tent fold, valid in every respect
Scaffold valid_multi_card(); ///< tent, step and v-fold side by side (the demo card)
Scaffold broken_tent_card(); ///< slopes shorter than feet: locks while opening
Scaffold five_bar_card();    ///< three linked patches between the bases: wobbles
/// `links` (at least 3) linked patches on an arch between the bases: links - 2 free motions.
Scaffold chain_card(int links);
Scaffold colliding_walls_card();   ///< two walls that meet at 40° and pass through below
Scaffold sticking_out_tent_card(); ///< apex 10 mm beyond the closed card

} // namespace popup::fixtures
