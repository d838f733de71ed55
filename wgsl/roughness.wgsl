// prepass — specular exponent ("roughness") stored in log range in 8 bits, as Killzone 2 stores
// it (Michal Valient, "Deferred Rendering in Killzone 2", Guerrilla Games, Develop Conference
// 2007), packed with an xyz8 normal into one RGBA8 texel as Resistance 2 keeps spec power in the
// normal buffer's alpha (Mark Lee, "Pre-lighting in Resistance 2", Insomniac Games, GDC 2009).
// Rust twin: src/roughness.rs. Tests: tests/roughness.rs.
// Spaces, handedness, depth conventions, byte order, units, NaN policy: README.md, "Conventions".
//
// code k in [0, 255] stands for the power max_power^(k/255): a power p encodes to the code
// nearest to 255·log2(p)/log2(max_power) (ties upwards). Equal steps in log2 keep the relative
// step size constant, 2^(log2(max_power)/255), so low powers (rough surfaces) keep precision.
//
// When max_power is a power of two, 2^L with integer L in [1, 127] (8192 = 2^13), both
// directions use only integer operations and two tables, so they are exact on every adapter
// and bit-identical to the Rust twin:
//   decode: k·L = 255·q + r, so max_power^(k/255) = 2^q · 2^(r/255); the table holds 2^(r/255)
//           correctly rounded and adding q to the exponent field is exact.
//   encode: the boundary between codes j and j+1 is T_j = 2^((2j+1)·L/510) = 2^Q · 2^(R/510);
//           the table holds the smallest f32 >= 2^(R/510), so for any f32 p the comparison
//           p >= T_j is decided exactly by comparing bit patterns. A log2 estimate (error far
//           below half a code) picks the candidate; the boundaries on either side correct it.
// Any other max_power in (1, 2^127) uses log2/exp2 (see the twin's docs for the bound).
//
// Bad input (same on both sides): max_power NaN or <= 1 leaves only code 0 / power 1;
// max_power above 2^127 (+Inf included) acts as 2^127. Powers: NaN, negative, -0, 0, subnormal
// and anything <= 1 encode to 0; +Inf and anything >= max_power encode to 255. Codes above 255
// decode as 255.

// Cost note: the tables are `var<private>` that nothing writes. As `const` arrays, naga copies
// the whole array into a local for every runtime-indexed access (lavapipe: 14x slower than the
// private tables over 1.1e8 encodes); a private variable is initialised once per invocation.
// (A 510-case switch instead of the array returned wrong entries for 432 of 510 cases on
// lavapipe / Mesa 22.3.6.) The encoder looks boundaries up only for the ~0.8% of powers within
// 2^-8 codes of one.

// 2^(r/255) for r = 0..254, correctly rounded to f32 (bit patterns).
var<private> LOG_ROUGHNESS_EXP2_STEPS: array<u32, 255> = array<u32, 255>(
    0x3f800000u, 0x3f805931u, 0x3f80b2a0u, 0x3f810c4eu, 0x3f81663au, 0x3f81c065u, 0x3f821aceu, 0x3f827577u,
    0x3f82d05fu, 0x3f832b86u, 0x3f8386edu, 0x3f83e293u, 0x3f843e79u, 0x3f849a9fu, 0x3f84f706u, 0x3f8553acu,
    0x3f85b094u, 0x3f860dbcu, 0x3f866b25u, 0x3f86c8cfu, 0x3f8726bau, 0x3f8784e7u, 0x3f87e356u, 0x3f884206u,
    0x3f88a0f8u, 0x3f89002cu, 0x3f895fa3u, 0x3f89bf5cu, 0x3f8a1f58u, 0x3f8a7f97u, 0x3f8ae019u, 0x3f8b40deu,
    0x3f8ba1e7u, 0x3f8c0333u, 0x3f8c64c3u, 0x3f8cc697u, 0x3f8d28afu, 0x3f8d8b0bu, 0x3f8dedacu, 0x3f8e5092u,
    0x3f8eb3bdu, 0x3f8f172du, 0x3f8f7ae2u, 0x3f8fdedcu, 0x3f90431cu, 0x3f90a7a2u, 0x3f910c6eu, 0x3f917181u,
    0x3f91d6d9u, 0x3f923c79u, 0x3f92a25fu, 0x3f93088cu, 0x3f936f01u, 0x3f93d5bcu, 0x3f943cc0u, 0x3f94a40bu,
    0x3f950b9eu, 0x3f957379u, 0x3f95db9du, 0x3f964409u, 0x3f96acbeu, 0x3f9715bcu, 0x3f977f03u, 0x3f97e894u,
    0x3f98526eu, 0x3f98bc92u, 0x3f9926ffu, 0x3f9991b7u, 0x3f99fcb9u, 0x3f9a6806u, 0x3f9ad39eu, 0x3f9b3f80u,
    0x3f9babaeu, 0x3f9c1827u, 0x3f9c84ecu, 0x3f9cf1fdu, 0x3f9d5f59u, 0x3f9dcd02u, 0x3f9e3af7u, 0x3f9ea939u,
    0x3f9f17c7u, 0x3f9f86a3u, 0x3f9ff5ccu, 0x3fa06542u, 0x3fa0d506u, 0x3fa14518u, 0x3fa1b578u, 0x3fa22626u,
    0x3fa29723u, 0x3fa3086eu, 0x3fa37a09u, 0x3fa3ebf2u, 0x3fa45e2bu, 0x3fa4d0b4u, 0x3fa5438cu, 0x3fa5b6b5u,
    0x3fa62a2du, 0x3fa69df6u, 0x3fa71210u, 0x3fa7867bu, 0x3fa7fb37u, 0x3fa87044u, 0x3fa8e5a3u, 0x3fa95b53u,
    0x3fa9d156u, 0x3faa47aau, 0x3faabe52u, 0x3fab354bu, 0x3fabac98u, 0x3fac2438u, 0x3fac9c2bu, 0x3fad1472u,
    0x3fad8d0du, 0x3fae05fcu, 0x3fae7f3fu, 0x3faef8d6u, 0x3faf72c2u, 0x3fafed03u, 0x3fb0679au, 0x3fb0e285u,
    0x3fb15dc7u, 0x3fb1d95eu, 0x3fb2554cu, 0x3fb2d18fu, 0x3fb34e2au, 0x3fb3cb1bu, 0x3fb44863u, 0x3fb4c603u,
    0x3fb543fau, 0x3fb5c249u, 0x3fb640efu, 0x3fb6bfefu, 0x3fb73f46u, 0x3fb7bef6u, 0x3fb83f00u, 0x3fb8bf62u,
    0x3fb9401eu, 0x3fb9c134u, 0x3fba42a4u, 0x3fbac46du, 0x3fbb4692u, 0x3fbbc911u, 0x3fbc4bebu, 0x3fbccf20u,
    0x3fbd52b0u, 0x3fbdd69cu, 0x3fbe5ae4u, 0x3fbedf89u, 0x3fbf6489u, 0x3fbfe9e7u, 0x3fc06fa1u, 0x3fc0f5b9u,
    0x3fc17c2du, 0x3fc20300u, 0x3fc28a31u, 0x3fc311bfu, 0x3fc399adu, 0x3fc421f9u, 0x3fc4aaa4u, 0x3fc533aeu,
    0x3fc5bd17u, 0x3fc646e1u, 0x3fc6d10au, 0x3fc75b94u, 0x3fc7e67eu, 0x3fc871c9u, 0x3fc8fd75u, 0x3fc98982u,
    0x3fca15f1u, 0x3fcaa2c2u, 0x3fcb2ff5u, 0x3fcbbd8bu, 0x3fcc4b83u, 0x3fccd9ddu, 0x3fcd689cu, 0x3fcdf7bdu,
    0x3fce8742u, 0x3fcf172cu, 0x3fcfa779u, 0x3fd0382cu, 0x3fd0c943u, 0x3fd15abfu, 0x3fd1eca0u, 0x3fd27ee7u,
    0x3fd31194u, 0x3fd3a4a8u, 0x3fd43821u, 0x3fd4cc02u, 0x3fd56049u, 0x3fd5f4f8u, 0x3fd68a0fu, 0x3fd71f8du,
    0x3fd7b573u, 0x3fd84bc2u, 0x3fd8e27au, 0x3fd9799bu, 0x3fda1125u, 0x3fdaa919u, 0x3fdb4176u, 0x3fdbda3eu,
    0x3fdc7370u, 0x3fdd0d0du, 0x3fdda715u, 0x3fde4188u, 0x3fdedc67u, 0x3fdf77b2u, 0x3fe01369u, 0x3fe0af8cu,
    0x3fe14c1cu, 0x3fe1e91au, 0x3fe28685u, 0x3fe3245du, 0x3fe3c2a4u, 0x3fe46158u, 0x3fe5007cu, 0x3fe5a00eu,
    0x3fe6400fu, 0x3fe6e080u, 0x3fe78161u, 0x3fe822b2u, 0x3fe8c473u, 0x3fe966a5u, 0x3fea0948u, 0x3feaac5cu,
    0x3feb4fe2u, 0x3febf3dau, 0x3fec9844u, 0x3fed3d21u, 0x3fede271u, 0x3fee8833u, 0x3fef2e6au, 0x3fefd514u,
    0x3ff07c32u, 0x3ff123c5u, 0x3ff1cbccu, 0x3ff27449u, 0x3ff31d3au, 0x3ff3c6a2u, 0x3ff47080u, 0x3ff51ad4u,
    0x3ff5c59fu, 0x3ff670e0u, 0x3ff71c99u, 0x3ff7c8cau, 0x3ff87573u, 0x3ff92294u, 0x3ff9d02eu, 0x3ffa7e40u,
    0x3ffb2cccu, 0x3ffbdbd2u, 0x3ffc8b51u, 0x3ffd3b4bu, 0x3ffdebc0u, 0x3ffe9cafu, 0x3fff4e1au,
);


// The smallest f32 >= 2^(r/510) for r = 0..509 (bit patterns): code boundaries rounded up.
var<private> LOG_ROUGHNESS_BOUNDARY_STEPS: array<u32, 510> = array<u32, 510>(
    0x3f800000u, 0x3f802c91u, 0x3f805932u, 0x3f8085e2u, 0x3f80b2a1u, 0x3f80df70u, 0x3f810c4fu, 0x3f81393du,
    0x3f81663bu, 0x3f819348u, 0x3f81c065u, 0x3f81ed92u, 0x3f821acfu, 0x3f82481bu, 0x3f827578u, 0x3f82a2e4u,
    0x3f82d05fu, 0x3f82fdebu, 0x3f832b86u, 0x3f835932u, 0x3f8386edu, 0x3f83b4b8u, 0x3f83e293u, 0x3f84107eu,
    0x3f843e79u, 0x3f846c85u, 0x3f849aa0u, 0x3f84c8cbu, 0x3f84f706u, 0x3f852551u, 0x3f8553adu, 0x3f858218u,
    0x3f85b094u, 0x3f85df20u, 0x3f860dbcu, 0x3f863c69u, 0x3f866b25u, 0x3f8699f2u, 0x3f86c8cfu, 0x3f86f7bdu,
    0x3f8726bbu, 0x3f8755c9u, 0x3f8784e8u, 0x3f87b417u, 0x3f87e356u, 0x3f8812a6u, 0x3f884206u, 0x3f887177u,
    0x3f88a0f9u, 0x3f88d08au, 0x3f89002du, 0x3f892fe0u, 0x3f895fa4u, 0x3f898f78u, 0x3f89bf5du, 0x3f89ef52u,
    0x3f8a1f59u, 0x3f8a4f70u, 0x3f8a7f98u, 0x3f8aafd0u, 0x3f8ae019u, 0x3f8b1074u, 0x3f8b40dfu, 0x3f8b715au,
    0x3f8ba1e7u, 0x3f8bd285u, 0x3f8c0333u, 0x3f8c33f3u, 0x3f8c64c3u, 0x3f8c95a5u, 0x3f8cc697u, 0x3f8cf79bu,
    0x3f8d28afu, 0x3f8d59d5u, 0x3f8d8b0cu, 0x3f8dbc54u, 0x3f8dedadu, 0x3f8e1f17u, 0x3f8e5093u, 0x3f8e821fu,
    0x3f8eb3bdu, 0x3f8ee56cu, 0x3f8f172du, 0x3f8f48ffu, 0x3f8f7ae2u, 0x3f8facd7u, 0x3f8fdeddu, 0x3f9010f4u,
    0x3f90431du, 0x3f907557u, 0x3f90a7a3u, 0x3f90da00u, 0x3f910c6fu, 0x3f913eefu, 0x3f917181u, 0x3f91a425u,
    0x3f91d6dau, 0x3f9209a1u, 0x3f923c79u, 0x3f926f64u, 0x3f92a260u, 0x3f92d56du, 0x3f93088du, 0x3f933bbeu,
    0x3f936f01u, 0x3f93a256u, 0x3f93d5bdu, 0x3f940936u, 0x3f943cc0u, 0x3f94705du, 0x3f94a40bu, 0x3f94d7ccu,
    0x3f950b9fu, 0x3f953f83u, 0x3f95737au, 0x3f95a783u, 0x3f95db9du, 0x3f960fcau, 0x3f96440au, 0x3f96785bu,
    0x3f96acbfu, 0x3f96e135u, 0x3f9715bdu, 0x3f974a57u, 0x3f977f04u, 0x3f97b3c3u, 0x3f97e894u, 0x3f981d78u,
    0x3f98526eu, 0x3f988777u, 0x3f98bc92u, 0x3f98f1c0u, 0x3f992700u, 0x3f995c52u, 0x3f9991b8u, 0x3f99c72fu,
    0x3f99fcbau, 0x3f9a3257u, 0x3f9a6807u, 0x3f9a9dc9u, 0x3f9ad39eu, 0x3f9b0986u, 0x3f9b3f81u, 0x3f9b758eu,
    0x3f9babafu, 0x3f9be1e2u, 0x3f9c1828u, 0x3f9c4e81u, 0x3f9c84edu, 0x3f9cbb6bu, 0x3f9cf1fdu, 0x3f9d28a2u,
    0x3f9d5f5au, 0x3f9d9624u, 0x3f9dcd02u, 0x3f9e03f3u, 0x3f9e3af7u, 0x3f9e720fu, 0x3f9ea939u, 0x3f9ee077u,
    0x3f9f17c8u, 0x3f9f4f2cu, 0x3f9f86a3u, 0x3f9fbe2eu, 0x3f9ff5ccu, 0x3fa02d7eu, 0x3fa06542u, 0x3fa09d1bu,
    0x3fa0d506u, 0x3fa10d06u, 0x3fa14518u, 0x3fa17d3eu, 0x3fa1b578u, 0x3fa1edc6u, 0x3fa22627u, 0x3fa25e9bu,
    0x3fa29723u, 0x3fa2cfbfu, 0x3fa3086fu, 0x3fa34132u, 0x3fa37a09u, 0x3fa3b2f4u, 0x3fa3ebf3u, 0x3fa42505u,
    0x3fa45e2cu, 0x3fa49766u, 0x3fa4d0b4u, 0x3fa50a17u, 0x3fa5438du, 0x3fa57d17u, 0x3fa5b6b5u, 0x3fa5f067u,
    0x3fa62a2eu, 0x3fa66408u, 0x3fa69df7u, 0x3fa6d7fau, 0x3fa71211u, 0x3fa74c3cu, 0x3fa7867bu, 0x3fa7c0cfu,
    0x3fa7fb37u, 0x3fa835b4u, 0x3fa87044u, 0x3fa8aaeau, 0x3fa8e5a3u, 0x3fa92071u, 0x3fa95b54u, 0x3fa9964bu,
    0x3fa9d156u, 0x3faa0c76u, 0x3faa47abu, 0x3faa82f4u, 0x3faabe52u, 0x3faaf9c5u, 0x3fab354cu, 0x3fab70e8u,
    0x3fabac99u, 0x3fabe85eu, 0x3fac2439u, 0x3fac6028u, 0x3fac9c2cu, 0x3facd845u, 0x3fad1473u, 0x3fad50b6u,
    0x3fad8d0du, 0x3fadc97au, 0x3fae05fcu, 0x3fae4293u, 0x3fae7f3fu, 0x3faebc00u, 0x3faef8d7u, 0x3faf35c2u,
    0x3faf72c3u, 0x3fafafd9u, 0x3fafed04u, 0x3fb02a44u, 0x3fb0679au, 0x3fb0a505u, 0x3fb0e286u, 0x3fb1201cu,
    0x3fb15dc7u, 0x3fb19b88u, 0x3fb1d95fu, 0x3fb2174bu, 0x3fb2554cu, 0x3fb29363u, 0x3fb2d190u, 0x3fb30fd2u,
    0x3fb34e2au, 0x3fb38c98u, 0x3fb3cb1bu, 0x3fb409b5u, 0x3fb44864u, 0x3fb48728u, 0x3fb4c603u, 0x3fb504f4u,
    0x3fb543fau, 0x3fb58317u, 0x3fb5c249u, 0x3fb60191u, 0x3fb640f0u, 0x3fb68064u, 0x3fb6bfefu, 0x3fb6ff90u,
    0x3fb73f47u, 0x3fb77f14u, 0x3fb7bef7u, 0x3fb7fef0u, 0x3fb83f00u, 0x3fb87f26u, 0x3fb8bf63u, 0x3fb8ffb6u,
    0x3fb9401fu, 0x3fb9809eu, 0x3fb9c134u, 0x3fba01e1u, 0x3fba42a4u, 0x3fba837eu, 0x3fbac46eu, 0x3fbb0575u,
    0x3fbb4692u, 0x3fbb87c6u, 0x3fbbc911u, 0x3fbc0a73u, 0x3fbc4bebu, 0x3fbc8d7au, 0x3fbccf20u, 0x3fbd10ddu,
    0x3fbd52b1u, 0x3fbd949bu, 0x3fbdd69du, 0x3fbe18b5u, 0x3fbe5ae5u, 0x3fbe9d2cu, 0x3fbedf89u, 0x3fbf21feu,
    0x3fbf648au, 0x3fbfa72du, 0x3fbfe9e7u, 0x3fc02cb9u, 0x3fc06fa2u, 0x3fc0b2a2u, 0x3fc0f5b9u, 0x3fc138e8u,
    0x3fc17c2eu, 0x3fc1bf8cu, 0x3fc20301u, 0x3fc2468du, 0x3fc28a31u, 0x3fc2cdedu, 0x3fc311c0u, 0x3fc355abu,
    0x3fc399adu, 0x3fc3ddc7u, 0x3fc421f9u, 0x3fc46643u, 0x3fc4aaa4u, 0x3fc4ef1du, 0x3fc533aeu, 0x3fc57857u,
    0x3fc5bd18u, 0x3fc601f1u, 0x3fc646e1u, 0x3fc68beau, 0x3fc6d10bu, 0x3fc71643u, 0x3fc75b94u, 0x3fc7a0fdu,
    0x3fc7e67eu, 0x3fc82c18u, 0x3fc871c9u, 0x3fc8b793u, 0x3fc8fd76u, 0x3fc94370u, 0x3fc98983u, 0x3fc9cfaeu,
    0x3fca15f2u, 0x3fca5c4eu, 0x3fcaa2c3u, 0x3fcae950u, 0x3fcb2ff6u, 0x3fcb76b4u, 0x3fcbbd8bu, 0x3fcc047bu,
    0x3fcc4b83u, 0x3fcc92a4u, 0x3fccd9deu, 0x3fcd2131u, 0x3fcd689cu, 0x3fcdb020u, 0x3fcdf7beu, 0x3fce3f74u,
    0x3fce8743u, 0x3fcecf2bu, 0x3fcf172cu, 0x3fcf5f47u, 0x3fcfa77au, 0x3fcfefc6u, 0x3fd0382cu, 0x3fd080abu,
    0x3fd0c943u, 0x3fd111f4u, 0x3fd15abfu, 0x3fd1a3a3u, 0x3fd1eca1u, 0x3fd235b7u, 0x3fd27ee8u, 0x3fd2c831u,
    0x3fd31195u, 0x3fd35b12u, 0x3fd3a4a8u, 0x3fd3ee58u, 0x3fd43822u, 0x3fd48205u, 0x3fd4cc02u, 0x3fd51619u,
    0x3fd5604au, 0x3fd5aa94u, 0x3fd5f4f9u, 0x3fd63f77u, 0x3fd68a0fu, 0x3fd6d4c1u, 0x3fd71f8du, 0x3fd76a74u,
    0x3fd7b574u, 0x3fd8008eu, 0x3fd84bc3u, 0x3fd89712u, 0x3fd8e27bu, 0x3fd92dfeu, 0x3fd9799bu, 0x3fd9c553u,
    0x3fda1125u, 0x3fda5d12u, 0x3fdaa919u, 0x3fdaf53bu, 0x3fdb4177u, 0x3fdb8dcdu, 0x3fdbda3eu, 0x3fdc26cau,
    0x3fdc7370u, 0x3fdcc031u, 0x3fdd0d0du, 0x3fdd5a04u, 0x3fdda715u, 0x3fddf441u, 0x3fde4188u, 0x3fde8eeau,
    0x3fdedc67u, 0x3fdf29ffu, 0x3fdf77b2u, 0x3fdfc580u, 0x3fe01369u, 0x3fe0616du, 0x3fe0af8du, 0x3fe0fdc7u,
    0x3fe14c1du, 0x3fe19a8eu, 0x3fe1e91au, 0x3fe237c2u, 0x3fe28685u, 0x3fe2d564u, 0x3fe3245eu, 0x3fe37373u,
    0x3fe3c2a4u, 0x3fe411f1u, 0x3fe46159u, 0x3fe4b0ddu, 0x3fe5007cu, 0x3fe55038u, 0x3fe5a00fu, 0x3fe5f001u,
    0x3fe64010u, 0x3fe6903au, 0x3fe6e081u, 0x3fe730e3u, 0x3fe78162u, 0x3fe7d1fcu, 0x3fe822b2u, 0x3fe87385u,
    0x3fe8c474u, 0x3fe9157fu, 0x3fe966a6u, 0x3fe9b7e9u, 0x3fea0949u, 0x3fea5ac5u, 0x3feaac5du, 0x3feafe12u,
    0x3feb4fe3u, 0x3feba1d0u, 0x3febf3dbu, 0x3fec4601u, 0x3fec9845u, 0x3feceaa5u, 0x3fed3d22u, 0x3fed8fbbu,
    0x3fede271u, 0x3fee3544u, 0x3fee8834u, 0x3feedb41u, 0x3fef2e6au, 0x3fef81b1u, 0x3fefd514u, 0x3ff02895u,
    0x3ff07c32u, 0x3ff0cfedu, 0x3ff123c5u, 0x3ff177bau, 0x3ff1cbcdu, 0x3ff21ffcu, 0x3ff27449u, 0x3ff2c8b3u,
    0x3ff31d3bu, 0x3ff371e0u, 0x3ff3c6a3u, 0x3ff41b83u, 0x3ff47080u, 0x3ff4c59cu, 0x3ff51ad4u, 0x3ff5702bu,
    0x3ff5c59fu, 0x3ff61b31u, 0x3ff670e1u, 0x3ff6c6aeu, 0x3ff71c9au, 0x3ff772a3u, 0x3ff7c8cbu, 0x3ff81f10u,
    0x3ff87573u, 0x3ff8cbf5u, 0x3ff92294u, 0x3ff97952u, 0x3ff9d02eu, 0x3ffa2728u, 0x3ffa7e41u, 0x3ffad578u,
    0x3ffb2ccdu, 0x3ffb8440u, 0x3ffbdbd2u, 0x3ffc3383u, 0x3ffc8b52u, 0x3ffce33fu, 0x3ffd3b4cu, 0x3ffd9377u,
    0x3ffdebc0u, 0x3ffe4428u, 0x3ffe9cb0u, 0x3ffef555u, 0x3fff4e1au, 0x3fffa6feu,
);

// log2(max_power) when max_power, after the bad-input rules, is a power of two 2^L with
// L in [1, 127]; 0 when the range is degenerate (max_power NaN or <= 1); 0xffffffff otherwise
// (a general max_power, handled with log2/exp2).
fn log_roughness_range_log2(max_power: f32) -> u32 {
    let b = bitcast<u32>(max_power);
    if ((b & 0x7fffffffu) > 0x7f800000u || (b >> 31u) != 0u || b <= 0x3f800000u) {
        return 0u;
    }
    if (b >= 0x7f000000u) {
        return 127u; // 2^127 and above, +Inf included
    }
    if ((b & 0x7fffffu) == 0u) {
        return (b >> 23u) - 127u;
    }
    return 0xffffffffu;
}

// Bits of the boundary between codes j and j+1 for max_power = 2^l.
fn log_roughness_boundary_bits(j: u32, l: u32) -> u32 {
    let n = (2u * j + 1u) * l;
    return LOG_ROUGHNESS_BOUNDARY_STEPS[n % 510u] + ((n / 510u) << 23u);
}

// The code of power: nearest to 255·log2(power)/log2(max_power), ties upwards.
fn encode_log_roughness(power: f32, max_power: f32) -> u32 {
    let l = log_roughness_range_log2(max_power);
    let b = bitcast<u32>(power);
    // NaN, negative (sign bit), and everything up to 1.0 encode to 0.
    if (l == 0u || (b & 0x7fffffffu) > 0x7f800000u || (b >> 31u) != 0u || b <= 0x3f800000u) {
        return 0u;
    }
    // +inf (from its bits) is above every max_power: no log2 of an infinity.
    if (b == 0x7f800000u) {
        return 255u;
    }
    if (l != 0xffffffffu) {
        // Candidate from log2: its error (3 ULP, or 2^-21 absolute near 1) is far below half a
        // code, so the exact code is the candidate or a neighbour. Positive floats order like
        // their bit patterns: compare with the rounded-up boundaries either side.
        let t = 255.0 * log2(power) / f32(l);
        var k = u32(clamp(floor(t + 0.5), 0.0, 255.0));
        // Far from a boundary (more than 2^-8 codes, 30x the estimate's error) the candidate is
        // the code; only the ~0.8% of powers nearer one look the boundaries up.
        if (abs(fract(t) - 0.5) < 0.00390625) {
            if (k > 0u && b < log_roughness_boundary_bits(k - 1u, l)) {
                k = k - 1u;
            } else if (k < 255u && b >= log_roughness_boundary_bits(k, l)) {
                k = k + 1u;
            }
        }
        return k;
    }
    if (b >= bitcast<u32>(max_power)) {
        return 255u;
    }
    let t = 255.0 * log2(power) / log2(max_power);
    return u32(clamp(floor(t + 0.5), 0.0, 255.0));
}

// The power max_power^(k/255) that code k stands for; codes above 255 decode as 255.
fn decode_log_roughness(code: u32, max_power: f32) -> f32 {
    let k = min(code, 255u);
    let l = log_roughness_range_log2(max_power);
    if (l == 0u) {
        return 1.0;
    }
    if (l != 0xffffffffu) {
        let n = k * l;
        return bitcast<f32>(LOG_ROUGHNESS_EXP2_STEPS[n % 255u] + ((n / 255u) << 23u));
    }
    if (k == 255u) {
        return max_power;
    }
    return exp2(f32(k) * log2(max_power) / 255.0);
}

// One RGBA8 texel: an xyz8 normal in bytes 0-2 (r, g, b; as encode_normal_xyz8 packs it) and the
// roughness code in byte 3 (alpha). Byte 3 of normal_xyz8 is ignored; codes above 255 saturate.
fn pack_normal_xyz8_log_roughness(normal_xyz8: u32, code: u32) -> u32 {
    return (normal_xyz8 & 0xffffffu) | (min(code, 255u) << 24u);
}

// The packed xyz8 normal of such a texel (bytes 0-2, byte 3 zero).
fn normal_xyz8_from_log_roughness_texel(texel: u32) -> u32 {
    return texel & 0xffffffu;
}

// The roughness code of such a texel (byte 3).
fn log_roughness_code_from_texel(texel: u32) -> u32 {
    return texel >> 24u;
}
