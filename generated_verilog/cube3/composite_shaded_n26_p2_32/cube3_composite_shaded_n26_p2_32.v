// Cube-3 composite_shaded_n26_p2_32: the integrable top (docs/integration.md). One clock; `reset` is
// synchronous, active high, where the build has one. Instantiation:
//
//   cube3_composite_shaded_n26_p2_32 u_render (
//     .clock(clock),
//     .host_write(host_write),
//     .host_address(host_address),
//     .host_data(host_data),
//     .start(start),
//     .done(done),
//     .pixel_r(pixel_r),
//     .pixel_g(pixel_g),
//     .pixel_b(pixel_b),
//     .pixel_a(pixel_a),
//     .has_sample(has_sample),
//     .ext_addr_0(ext_addr_0),
//     .ext_addr_1(ext_addr_1),
//     .ext_data_0(ext_data_0),
//     .ext_data_1(ext_data_1),
//     .load_enable(load_enable),
//     .load_module(load_module),
//     .load_address(load_address),
//     .load_data(load_data)
//   );
module cube3_composite_shaded_n26_p2_32 (
    input  wire clock,
    input  wire host_write,
    input  wire [23:0] host_address,
    input  wire [63:0] host_data,
    input  wire start,
    output wire done,
    output wire [31:0] pixel_r,
    output wire [15:0] pixel_g,
    output wire [15:0] pixel_b,
    output wire [15:0] pixel_a,
    output wire has_sample,
    output wire [31:0] ext_addr_0,
    output wire [31:0] ext_addr_1,
    input  wire [15:0] ext_data_0,
    input  wire [15:0] ext_data_1,
    input  wire load_enable,
    input  wire [7:0] load_module,
    input  wire [31:0] load_address,
    input  wire [15:0] load_data
);
    top core (
        .clock(clock),
        .host_write(host_write),
        .host_address(host_address),
        .host_data(host_data),
        .start(start),
        .done(done),
        .pixel_r(pixel_r),
        .pixel_g(pixel_g),
        .pixel_b(pixel_b),
        .pixel_a(pixel_a),
        .has_sample(has_sample),
        .ext_addr$0(ext_addr_0),
        .ext_addr$1(ext_addr_1),
        .ext_data$0(ext_data_0),
        .ext_data$1(ext_data_1),
        .load_enable(load_enable),
        .load_module(load_module),
        .load_address(load_address),
        .load_data(load_data)
    );
endmodule
