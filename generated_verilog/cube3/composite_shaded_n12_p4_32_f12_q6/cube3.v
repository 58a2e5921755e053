module top$pipeline(clock,host_write,host_address,host_data,start,valid,cur$0,cur$1,cur$2,cur$3,next$0,next$1,next$2,next$3,done,pixel_r,pixel_g,pixel_b,pixel_a,has_sample);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  start;
    input wire  valid;
    input wire  [15:0] cur$0;
    input wire  [15:0] cur$1;
    input wire  [15:0] cur$2;
    input wire  [15:0] cur$3;
    input wire  [15:0] next$0;
    input wire  [15:0] next$1;
    input wire  [15:0] next$2;
    input wire  [15:0] next$3;
    output reg  done;
    output reg  [31:0] pixel_r;
    output reg  [15:0] pixel_g;
    output reg  [15:0] pixel_b;
    output reg  [15:0] pixel_a;
    output reg  has_sample;
    
    // Constant declarations
    localparam  cast_bit = 8'h8;
    localparam  gradients = 1'b1;
    localparam  shaded = 1'b1;
    localparam  xray = 1'b0;
    localparam  half = 'h8;
    localparam  frac = 8'h4;
    localparam  row_shift = 8'h0;
    localparam  lane_bit$0 = 'h1;
    localparam  lane_bit$1 = 'h2;
    localparam  lane_bit$2 = 'h4;
    localparam  lane_bit$3 = 'h8;
    localparam  lane_bit$4 = 'h10;
    localparam  lane_bit$5 = 'h20;
    localparam  lane_bit$6 = 'h40;
    localparam  lane_bit$7 = 'h80;
    localparam  inner_bit$0 = 'h10000;
    localparam  inner_bit$1 = 'h20000;
    localparam  inner_bit$2 = 'h40000;
    localparam  inner_bit$3 = 'h80000;
    localparam  inner_bit$4 = 'h100000;
    localparam  inner_bit$5 = 'h200000;
    localparam  inner_bit$6 = 'h400000;
    localparam  inner_bit$7 = 'h800000;
    
    // Stub signals
    reg  regs$clock;
    reg  regs$host_write;
    reg  [23:0] regs$host_address;
    reg  [63:0] regs$host_data;
    wire  [63:0] regs$q$0;
    wire  [63:0] regs$q$1;
    wire  [63:0] regs$q$2;
    reg  control$clock;
    reg  control$host_write;
    reg  [23:0] control$host_address;
    reg  [63:0] control$host_data;
    reg  control$start;
    reg  control$valid;
    wire  control$first;
    wire  control$unit_valid;
    wire  control$unit_first;
    wire  control$unit_last;
    wire  control$unit_cast;
    wire  [15:0] control$wx$0;
    wire  [15:0] control$wx$1;
    wire  [15:0] control$wx$2;
    wire  [15:0] control$wx$3;
    wire  [15:0] control$wy$0;
    wire  [15:0] control$wy$1;
    wire  [15:0] control$wy$2;
    wire  [15:0] control$wy$3;
    wire  [7:0] control$in_volume;
    wire  [7:0] control$in_inner;
    wire  control$dx_neg;
    wire  [15:0] control$dx_mag;
    wire  control$dy_neg;
    wire  [15:0] control$dy_mag;
    reg  lanes$clock;
    reg  [15:0] lanes$cur$0;
    reg  [15:0] lanes$cur$1;
    reg  [15:0] lanes$cur$2;
    reg  [15:0] lanes$cur$3;
    reg  [15:0] lanes$next$0;
    reg  [15:0] lanes$next$1;
    reg  [15:0] lanes$next$2;
    reg  [15:0] lanes$next$3;
    reg  lanes$first;
    reg  [15:0] lanes$wx$0;
    reg  [15:0] lanes$wx$1;
    reg  [15:0] lanes$wx$2;
    reg  [15:0] lanes$wx$3;
    reg  [15:0] lanes$wy$0;
    reg  [15:0] lanes$wy$1;
    reg  [15:0] lanes$wy$2;
    reg  [15:0] lanes$wy$3;
    wire  [31:0] lanes$sample$0;
    wire  [31:0] lanes$sample$1;
    wire  [31:0] lanes$sample$2;
    wire  [31:0] lanes$sample$3;
    reg  [15:0] lanes$offset;
    reg  [15:0] lanes$line_last;
    reg  [31:0] flags_q$0$d;
    wire  [31:0] flags_q$0$q;
    reg  flags_q$0$clock;
    reg  [31:0] flags_q$1$d;
    wire  [31:0] flags_q$1$q;
    reg  flags_q$1$clock;
    reg  [31:0] flags_q$2$d;
    wire  [31:0] flags_q$2$q;
    reg  flags_q$2$clock;
    reg  [31:0] flags_q$3$d;
    wire  [31:0] flags_q$3$q;
    reg  flags_q$3$clock;
    reg  [31:0] flags_q$4$d;
    wire  [31:0] flags_q$4$q;
    reg  flags_q$4$clock;
    reg  [31:0] flags_q$5$d;
    wire  [31:0] flags_q$5$q;
    reg  flags_q$5$clock;
    reg  [31:0] flags_q$6$d;
    wire  [31:0] flags_q$6$q;
    reg  flags_q$6$clock;
    reg  flags_line$clock;
    reg  [31:0] flags_line$data_in;
    reg  flags_line$write_enable;
    wire  [31:0] flags_line$data_out;
    reg  [15:0] flags_line$last;
    reg  [31:0] shade_flags_q$0$d;
    wire  [31:0] shade_flags_q$0$q;
    reg  shade_flags_q$0$clock;
    reg  [31:0] shade_flags_q$1$d;
    wire  [31:0] shade_flags_q$1$q;
    reg  shade_flags_q$1$clock;
    reg  [31:0] shade_flags_q$2$d;
    wire  [31:0] shade_flags_q$2$q;
    reg  shade_flags_q$2$clock;
    reg  [31:0] shade_flags_q$3$d;
    wire  [31:0] shade_flags_q$3$q;
    reg  shade_flags_q$3$clock;
    reg  [31:0] shade_flags_q$4$d;
    wire  [31:0] shade_flags_q$4$q;
    reg  shade_flags_q$4$clock;
    reg  [31:0] shade_flags_q$5$d;
    wire  [31:0] shade_flags_q$5$q;
    reg  shade_flags_q$5$clock;
    reg  [31:0] shade_flags_q$6$d;
    wire  [31:0] shade_flags_q$6$q;
    reg  shade_flags_q$6$clock;
    reg  [31:0] shade_flags_q$7$d;
    wire  [31:0] shade_flags_q$7$q;
    reg  shade_flags_q$7$clock;
    reg  [31:0] shade_flags_q$8$d;
    wire  [31:0] shade_flags_q$8$q;
    reg  shade_flags_q$8$clock;
    reg  [31:0] shade_flags_q$9$d;
    wire  [31:0] shade_flags_q$9$q;
    reg  shade_flags_q$9$clock;
    reg  [31:0] shade_flags_q$10$d;
    wire  [31:0] shade_flags_q$10$q;
    reg  shade_flags_q$10$clock;
    reg  [31:0] shade_flags_q$11$d;
    wire  [31:0] shade_flags_q$11$q;
    reg  shade_flags_q$11$clock;
    reg  [31:0] shade_flags_q$12$d;
    wire  [31:0] shade_flags_q$12$q;
    reg  shade_flags_q$12$clock;
    reg  [31:0] shade_flags_q$13$d;
    wire  [31:0] shade_flags_q$13$q;
    reg  shade_flags_q$13$clock;
    reg  [31:0] shade_flags_q$14$d;
    wire  [31:0] shade_flags_q$14$q;
    reg  shade_flags_q$14$clock;
    reg  [31:0] shade_flags_q$15$d;
    wire  [31:0] shade_flags_q$15$q;
    reg  shade_flags_q$15$clock;
    reg  [31:0] rpc_flags_q$d;
    wire  [31:0] rpc_flags_q$q;
    reg  rpc_flags_q$clock;
    reg  [7:0] cast_q$d;
    wire  [7:0] cast_q$q;
    reg  cast_q$clock;
    reg  opacity$0$clock;
    reg  opacity$0$host_write;
    reg  [23:0] opacity$0$host_address;
    reg  [63:0] opacity$0$host_data;
    reg  [11:0] opacity$0$address;
    wire  [31:0] opacity$0$data;
    reg  opacity$1$clock;
    reg  opacity$1$host_write;
    reg  [23:0] opacity$1$host_address;
    reg  [63:0] opacity$1$host_data;
    reg  [11:0] opacity$1$address;
    wire  [31:0] opacity$1$data;
    reg  opacity$2$clock;
    reg  opacity$2$host_write;
    reg  [23:0] opacity$2$host_address;
    reg  [63:0] opacity$2$host_data;
    reg  [11:0] opacity$2$address;
    wire  [31:0] opacity$2$data;
    reg  opacity$3$clock;
    reg  opacity$3$host_write;
    reg  [23:0] opacity$3$host_address;
    reg  [63:0] opacity$3$host_data;
    reg  [11:0] opacity$3$address;
    wire  [31:0] opacity$3$data;
    reg  [31:0] leaf_q$0$d;
    wire  [31:0] leaf_q$0$q;
    reg  leaf_q$0$clock;
    reg  [31:0] leaf_q$1$d;
    wire  [31:0] leaf_q$1$q;
    reg  leaf_q$1$clock;
    reg  [31:0] leaf_q$2$d;
    wire  [31:0] leaf_q$2$q;
    reg  leaf_q$2$clock;
    reg  [31:0] leaf_q$3$d;
    wire  [31:0] leaf_q$3$q;
    reg  leaf_q$3$clock;
    reg  leaf_valid_q$0$d;
    wire  leaf_valid_q$0$q;
    reg  leaf_valid_q$0$clock;
    reg  leaf_valid_q$1$d;
    wire  leaf_valid_q$1$q;
    reg  leaf_valid_q$1$clock;
    reg  leaf_valid_q$2$d;
    wire  leaf_valid_q$2$q;
    reg  leaf_valid_q$2$clock;
    reg  leaf_valid_q$3$d;
    wire  leaf_valid_q$3$q;
    reg  leaf_valid_q$3$clock;
    reg  abc$clock;
    reg  abc$host_write;
    reg  [23:0] abc$host_address;
    reg  [63:0] abc$host_data;
    reg  [15:0] abc$ray_last;
    reg  [15:0] abc$line_last;
    reg  [31:0] abc$sample$0;
    reg  [31:0] abc$sample$1;
    reg  [31:0] abc$sample$2;
    reg  [31:0] abc$sample$3;
    reg  abc$dx_neg;
    reg  [15:0] abc$dx_mag;
    reg  abc$dy_neg;
    reg  [15:0] abc$dy_mag;
    wire  [31:0] abc$centre$0;
    wire  [31:0] abc$centre$1;
    wire  [31:0] abc$centre$2;
    wire  [31:0] abc$centre$3;
    wire  [31:0] abc$gx$0;
    wire  [31:0] abc$gx$1;
    wire  [31:0] abc$gx$2;
    wire  [31:0] abc$gx$3;
    wire  [31:0] abc$gy$0;
    wire  [31:0] abc$gy$1;
    wire  [31:0] abc$gy$2;
    wire  [31:0] abc$gy$3;
    wire  [31:0] abc$gz$0;
    wire  [31:0] abc$gz$1;
    wire  [31:0] abc$gz$2;
    wire  [31:0] abc$gz$3;
    reg  shade$0$clock;
    reg  shade$0$host_write;
    reg  [23:0] shade$0$host_address;
    reg  [63:0] shade$0$host_data;
    reg  [15:0] shade$0$value;
    reg  shade$0$invalid;
    reg  shade$0$at_edge;
    reg  shade$0$gx_neg;
    reg  [31:0] shade$0$gx_mag;
    reg  shade$0$gy_neg;
    reg  [31:0] shade$0$gy_mag;
    reg  shade$0$gz_neg;
    reg  [31:0] shade$0$gz_mag;
    wire  [31:0] shade$0$r;
    wire  [15:0] shade$0$g;
    wire  [15:0] shade$0$b;
    wire  [15:0] shade$0$a;
    wire  shade$0$valid;
    reg  shade$1$clock;
    reg  shade$1$host_write;
    reg  [23:0] shade$1$host_address;
    reg  [63:0] shade$1$host_data;
    reg  [15:0] shade$1$value;
    reg  shade$1$invalid;
    reg  shade$1$at_edge;
    reg  shade$1$gx_neg;
    reg  [31:0] shade$1$gx_mag;
    reg  shade$1$gy_neg;
    reg  [31:0] shade$1$gy_mag;
    reg  shade$1$gz_neg;
    reg  [31:0] shade$1$gz_mag;
    wire  [31:0] shade$1$r;
    wire  [15:0] shade$1$g;
    wire  [15:0] shade$1$b;
    wire  [15:0] shade$1$a;
    wire  shade$1$valid;
    reg  shade$2$clock;
    reg  shade$2$host_write;
    reg  [23:0] shade$2$host_address;
    reg  [63:0] shade$2$host_data;
    reg  [15:0] shade$2$value;
    reg  shade$2$invalid;
    reg  shade$2$at_edge;
    reg  shade$2$gx_neg;
    reg  [31:0] shade$2$gx_mag;
    reg  shade$2$gy_neg;
    reg  [31:0] shade$2$gy_mag;
    reg  shade$2$gz_neg;
    reg  [31:0] shade$2$gz_mag;
    wire  [31:0] shade$2$r;
    wire  [15:0] shade$2$g;
    wire  [15:0] shade$2$b;
    wire  [15:0] shade$2$a;
    wire  shade$2$valid;
    reg  shade$3$clock;
    reg  shade$3$host_write;
    reg  [23:0] shade$3$host_address;
    reg  [63:0] shade$3$host_data;
    reg  [15:0] shade$3$value;
    reg  shade$3$invalid;
    reg  shade$3$at_edge;
    reg  shade$3$gx_neg;
    reg  [31:0] shade$3$gx_mag;
    reg  shade$3$gy_neg;
    reg  [31:0] shade$3$gy_mag;
    reg  shade$3$gz_neg;
    reg  [31:0] shade$3$gz_mag;
    wire  [31:0] shade$3$r;
    wire  [15:0] shade$3$g;
    wire  [15:0] shade$3$b;
    wire  [15:0] shade$3$a;
    wire  shade$3$valid;
    reg  rpc$clock;
    reg  [31:0] rpc$leaf_r$0;
    reg  [31:0] rpc$leaf_r$1;
    reg  [31:0] rpc$leaf_r$2;
    reg  [31:0] rpc$leaf_r$3;
    reg  [15:0] rpc$leaf_g$0;
    reg  [15:0] rpc$leaf_g$1;
    reg  [15:0] rpc$leaf_g$2;
    reg  [15:0] rpc$leaf_g$3;
    reg  [15:0] rpc$leaf_b$0;
    reg  [15:0] rpc$leaf_b$1;
    reg  [15:0] rpc$leaf_b$2;
    reg  [15:0] rpc$leaf_b$3;
    reg  [15:0] rpc$leaf_a$0;
    reg  [15:0] rpc$leaf_a$1;
    reg  [15:0] rpc$leaf_a$2;
    reg  [15:0] rpc$leaf_a$3;
    reg  rpc$leaf_valid$0;
    reg  rpc$leaf_valid$1;
    reg  rpc$leaf_valid$2;
    reg  rpc$leaf_valid$3;
    reg  rpc$first;
    reg  rpc$last;
    wire  rpc$done;
    wire  [31:0] rpc$pixel_r;
    wire  [15:0] rpc$pixel_g;
    wire  [15:0] rpc$pixel_b;
    wire  [15:0] rpc$pixel_a;
    wire  rpc$has_sample;
    
    // Local signals
    reg  [31:0] leaf_flags;
    reg  pixel_cast;
    reg  [31:0] row$0;
    reg  [31:0] row$1;
    reg  [31:0] row$2;
    reg  [31:0] row$3;
    reg  [31:0] index$0;
    reg  [31:0] index$1;
    reg  [31:0] index$2;
    reg  [31:0] index$3;
    reg  [31:0] gx$0;
    reg  [31:0] gx$1;
    reg  [31:0] gx$2;
    reg  [31:0] gx$3;
    reg  [31:0] gy$0;
    reg  [31:0] gy$1;
    reg  [31:0] gy$2;
    reg  [31:0] gy$3;
    reg  [31:0] gz$0;
    reg  [31:0] gz$1;
    reg  [31:0] gz$2;
    reg  [31:0] gz$3;
    
    // Sub module instances
    top$pipeline$regs regs(
        .clock(regs$clock),
        .host_write(regs$host_write),
        .host_address(regs$host_address),
        .host_data(regs$host_data),
        .q$0(regs$q$0),
        .q$1(regs$q$1),
        .q$2(regs$q$2)
    );
    top$pipeline$control control(
        .clock(control$clock),
        .host_write(control$host_write),
        .host_address(control$host_address),
        .host_data(control$host_data),
        .start(control$start),
        .valid(control$valid),
        .first(control$first),
        .unit_valid(control$unit_valid),
        .unit_first(control$unit_first),
        .unit_last(control$unit_last),
        .unit_cast(control$unit_cast),
        .wx$0(control$wx$0),
        .wx$1(control$wx$1),
        .wx$2(control$wx$2),
        .wx$3(control$wx$3),
        .wy$0(control$wy$0),
        .wy$1(control$wy$1),
        .wy$2(control$wy$2),
        .wy$3(control$wy$3),
        .in_volume(control$in_volume),
        .in_inner(control$in_inner),
        .dx_neg(control$dx_neg),
        .dx_mag(control$dx_mag),
        .dy_neg(control$dy_neg),
        .dy_mag(control$dy_mag)
    );
    top$pipeline$lanes lanes(
        .clock(lanes$clock),
        .cur$0(lanes$cur$0),
        .cur$1(lanes$cur$1),
        .cur$2(lanes$cur$2),
        .cur$3(lanes$cur$3),
        .next$0(lanes$next$0),
        .next$1(lanes$next$1),
        .next$2(lanes$next$2),
        .next$3(lanes$next$3),
        .first(lanes$first),
        .wx$0(lanes$wx$0),
        .wx$1(lanes$wx$1),
        .wx$2(lanes$wx$2),
        .wx$3(lanes$wx$3),
        .wy$0(lanes$wy$0),
        .wy$1(lanes$wy$1),
        .wy$2(lanes$wy$2),
        .wy$3(lanes$wy$3),
        .sample$0(lanes$sample$0),
        .sample$1(lanes$sample$1),
        .sample$2(lanes$sample$2),
        .sample$3(lanes$sample$3),
        .offset(lanes$offset),
        .line_last(lanes$line_last)
    );
    top$pipeline$flags_q$0 flags_q$0(
        .d(flags_q$0$d),
        .q(flags_q$0$q),
        .clock(flags_q$0$clock)
    );
    top$pipeline$flags_q$1 flags_q$1(
        .d(flags_q$1$d),
        .q(flags_q$1$q),
        .clock(flags_q$1$clock)
    );
    top$pipeline$flags_q$2 flags_q$2(
        .d(flags_q$2$d),
        .q(flags_q$2$q),
        .clock(flags_q$2$clock)
    );
    top$pipeline$flags_q$3 flags_q$3(
        .d(flags_q$3$d),
        .q(flags_q$3$q),
        .clock(flags_q$3$clock)
    );
    top$pipeline$flags_q$4 flags_q$4(
        .d(flags_q$4$d),
        .q(flags_q$4$q),
        .clock(flags_q$4$clock)
    );
    top$pipeline$flags_q$5 flags_q$5(
        .d(flags_q$5$d),
        .q(flags_q$5$q),
        .clock(flags_q$5$clock)
    );
    top$pipeline$flags_q$6 flags_q$6(
        .d(flags_q$6$d),
        .q(flags_q$6$q),
        .clock(flags_q$6$clock)
    );
    top$pipeline$flags_line flags_line(
        .clock(flags_line$clock),
        .data_in(flags_line$data_in),
        .write_enable(flags_line$write_enable),
        .data_out(flags_line$data_out),
        .last(flags_line$last)
    );
    top$pipeline$shade_flags_q$0 shade_flags_q$0(
        .d(shade_flags_q$0$d),
        .q(shade_flags_q$0$q),
        .clock(shade_flags_q$0$clock)
    );
    top$pipeline$shade_flags_q$1 shade_flags_q$1(
        .d(shade_flags_q$1$d),
        .q(shade_flags_q$1$q),
        .clock(shade_flags_q$1$clock)
    );
    top$pipeline$shade_flags_q$2 shade_flags_q$2(
        .d(shade_flags_q$2$d),
        .q(shade_flags_q$2$q),
        .clock(shade_flags_q$2$clock)
    );
    top$pipeline$shade_flags_q$3 shade_flags_q$3(
        .d(shade_flags_q$3$d),
        .q(shade_flags_q$3$q),
        .clock(shade_flags_q$3$clock)
    );
    top$pipeline$shade_flags_q$4 shade_flags_q$4(
        .d(shade_flags_q$4$d),
        .q(shade_flags_q$4$q),
        .clock(shade_flags_q$4$clock)
    );
    top$pipeline$shade_flags_q$5 shade_flags_q$5(
        .d(shade_flags_q$5$d),
        .q(shade_flags_q$5$q),
        .clock(shade_flags_q$5$clock)
    );
    top$pipeline$shade_flags_q$6 shade_flags_q$6(
        .d(shade_flags_q$6$d),
        .q(shade_flags_q$6$q),
        .clock(shade_flags_q$6$clock)
    );
    top$pipeline$shade_flags_q$7 shade_flags_q$7(
        .d(shade_flags_q$7$d),
        .q(shade_flags_q$7$q),
        .clock(shade_flags_q$7$clock)
    );
    top$pipeline$shade_flags_q$8 shade_flags_q$8(
        .d(shade_flags_q$8$d),
        .q(shade_flags_q$8$q),
        .clock(shade_flags_q$8$clock)
    );
    top$pipeline$shade_flags_q$9 shade_flags_q$9(
        .d(shade_flags_q$9$d),
        .q(shade_flags_q$9$q),
        .clock(shade_flags_q$9$clock)
    );
    top$pipeline$shade_flags_q$10 shade_flags_q$10(
        .d(shade_flags_q$10$d),
        .q(shade_flags_q$10$q),
        .clock(shade_flags_q$10$clock)
    );
    top$pipeline$shade_flags_q$11 shade_flags_q$11(
        .d(shade_flags_q$11$d),
        .q(shade_flags_q$11$q),
        .clock(shade_flags_q$11$clock)
    );
    top$pipeline$shade_flags_q$12 shade_flags_q$12(
        .d(shade_flags_q$12$d),
        .q(shade_flags_q$12$q),
        .clock(shade_flags_q$12$clock)
    );
    top$pipeline$shade_flags_q$13 shade_flags_q$13(
        .d(shade_flags_q$13$d),
        .q(shade_flags_q$13$q),
        .clock(shade_flags_q$13$clock)
    );
    top$pipeline$shade_flags_q$14 shade_flags_q$14(
        .d(shade_flags_q$14$d),
        .q(shade_flags_q$14$q),
        .clock(shade_flags_q$14$clock)
    );
    top$pipeline$shade_flags_q$15 shade_flags_q$15(
        .d(shade_flags_q$15$d),
        .q(shade_flags_q$15$q),
        .clock(shade_flags_q$15$clock)
    );
    top$pipeline$rpc_flags_q rpc_flags_q(
        .d(rpc_flags_q$d),
        .q(rpc_flags_q$q),
        .clock(rpc_flags_q$clock)
    );
    top$pipeline$cast_q cast_q(
        .d(cast_q$d),
        .q(cast_q$q),
        .clock(cast_q$clock)
    );
    top$pipeline$opacity$0 opacity$0(
        .clock(opacity$0$clock),
        .host_write(opacity$0$host_write),
        .host_address(opacity$0$host_address),
        .host_data(opacity$0$host_data),
        .address(opacity$0$address),
        .data(opacity$0$data)
    );
    top$pipeline$opacity$1 opacity$1(
        .clock(opacity$1$clock),
        .host_write(opacity$1$host_write),
        .host_address(opacity$1$host_address),
        .host_data(opacity$1$host_data),
        .address(opacity$1$address),
        .data(opacity$1$data)
    );
    top$pipeline$opacity$2 opacity$2(
        .clock(opacity$2$clock),
        .host_write(opacity$2$host_write),
        .host_address(opacity$2$host_address),
        .host_data(opacity$2$host_data),
        .address(opacity$2$address),
        .data(opacity$2$data)
    );
    top$pipeline$opacity$3 opacity$3(
        .clock(opacity$3$clock),
        .host_write(opacity$3$host_write),
        .host_address(opacity$3$host_address),
        .host_data(opacity$3$host_data),
        .address(opacity$3$address),
        .data(opacity$3$data)
    );
    top$pipeline$leaf_q$0 leaf_q$0(
        .d(leaf_q$0$d),
        .q(leaf_q$0$q),
        .clock(leaf_q$0$clock)
    );
    top$pipeline$leaf_q$1 leaf_q$1(
        .d(leaf_q$1$d),
        .q(leaf_q$1$q),
        .clock(leaf_q$1$clock)
    );
    top$pipeline$leaf_q$2 leaf_q$2(
        .d(leaf_q$2$d),
        .q(leaf_q$2$q),
        .clock(leaf_q$2$clock)
    );
    top$pipeline$leaf_q$3 leaf_q$3(
        .d(leaf_q$3$d),
        .q(leaf_q$3$q),
        .clock(leaf_q$3$clock)
    );
    top$pipeline$leaf_valid_q$0 leaf_valid_q$0(
        .d(leaf_valid_q$0$d),
        .q(leaf_valid_q$0$q),
        .clock(leaf_valid_q$0$clock)
    );
    top$pipeline$leaf_valid_q$1 leaf_valid_q$1(
        .d(leaf_valid_q$1$d),
        .q(leaf_valid_q$1$q),
        .clock(leaf_valid_q$1$clock)
    );
    top$pipeline$leaf_valid_q$2 leaf_valid_q$2(
        .d(leaf_valid_q$2$d),
        .q(leaf_valid_q$2$q),
        .clock(leaf_valid_q$2$clock)
    );
    top$pipeline$leaf_valid_q$3 leaf_valid_q$3(
        .d(leaf_valid_q$3$d),
        .q(leaf_valid_q$3$q),
        .clock(leaf_valid_q$3$clock)
    );
    top$pipeline$abc abc(
        .clock(abc$clock),
        .host_write(abc$host_write),
        .host_address(abc$host_address),
        .host_data(abc$host_data),
        .ray_last(abc$ray_last),
        .line_last(abc$line_last),
        .sample$0(abc$sample$0),
        .sample$1(abc$sample$1),
        .sample$2(abc$sample$2),
        .sample$3(abc$sample$3),
        .dx_neg(abc$dx_neg),
        .dx_mag(abc$dx_mag),
        .dy_neg(abc$dy_neg),
        .dy_mag(abc$dy_mag),
        .centre$0(abc$centre$0),
        .centre$1(abc$centre$1),
        .centre$2(abc$centre$2),
        .centre$3(abc$centre$3),
        .gx$0(abc$gx$0),
        .gx$1(abc$gx$1),
        .gx$2(abc$gx$2),
        .gx$3(abc$gx$3),
        .gy$0(abc$gy$0),
        .gy$1(abc$gy$1),
        .gy$2(abc$gy$2),
        .gy$3(abc$gy$3),
        .gz$0(abc$gz$0),
        .gz$1(abc$gz$1),
        .gz$2(abc$gz$2),
        .gz$3(abc$gz$3)
    );
    top$pipeline$shade$0 shade$0(
        .clock(shade$0$clock),
        .host_write(shade$0$host_write),
        .host_address(shade$0$host_address),
        .host_data(shade$0$host_data),
        .value(shade$0$value),
        .invalid(shade$0$invalid),
        .at_edge(shade$0$at_edge),
        .gx_neg(shade$0$gx_neg),
        .gx_mag(shade$0$gx_mag),
        .gy_neg(shade$0$gy_neg),
        .gy_mag(shade$0$gy_mag),
        .gz_neg(shade$0$gz_neg),
        .gz_mag(shade$0$gz_mag),
        .r(shade$0$r),
        .g(shade$0$g),
        .b(shade$0$b),
        .a(shade$0$a),
        .valid(shade$0$valid)
    );
    top$pipeline$shade$1 shade$1(
        .clock(shade$1$clock),
        .host_write(shade$1$host_write),
        .host_address(shade$1$host_address),
        .host_data(shade$1$host_data),
        .value(shade$1$value),
        .invalid(shade$1$invalid),
        .at_edge(shade$1$at_edge),
        .gx_neg(shade$1$gx_neg),
        .gx_mag(shade$1$gx_mag),
        .gy_neg(shade$1$gy_neg),
        .gy_mag(shade$1$gy_mag),
        .gz_neg(shade$1$gz_neg),
        .gz_mag(shade$1$gz_mag),
        .r(shade$1$r),
        .g(shade$1$g),
        .b(shade$1$b),
        .a(shade$1$a),
        .valid(shade$1$valid)
    );
    top$pipeline$shade$2 shade$2(
        .clock(shade$2$clock),
        .host_write(shade$2$host_write),
        .host_address(shade$2$host_address),
        .host_data(shade$2$host_data),
        .value(shade$2$value),
        .invalid(shade$2$invalid),
        .at_edge(shade$2$at_edge),
        .gx_neg(shade$2$gx_neg),
        .gx_mag(shade$2$gx_mag),
        .gy_neg(shade$2$gy_neg),
        .gy_mag(shade$2$gy_mag),
        .gz_neg(shade$2$gz_neg),
        .gz_mag(shade$2$gz_mag),
        .r(shade$2$r),
        .g(shade$2$g),
        .b(shade$2$b),
        .a(shade$2$a),
        .valid(shade$2$valid)
    );
    top$pipeline$shade$3 shade$3(
        .clock(shade$3$clock),
        .host_write(shade$3$host_write),
        .host_address(shade$3$host_address),
        .host_data(shade$3$host_data),
        .value(shade$3$value),
        .invalid(shade$3$invalid),
        .at_edge(shade$3$at_edge),
        .gx_neg(shade$3$gx_neg),
        .gx_mag(shade$3$gx_mag),
        .gy_neg(shade$3$gy_neg),
        .gy_mag(shade$3$gy_mag),
        .gz_neg(shade$3$gz_neg),
        .gz_mag(shade$3$gz_mag),
        .r(shade$3$r),
        .g(shade$3$g),
        .b(shade$3$b),
        .a(shade$3$a),
        .valid(shade$3$valid)
    );
    top$pipeline$rpc rpc(
        .clock(rpc$clock),
        .leaf_r$0(rpc$leaf_r$0),
        .leaf_r$1(rpc$leaf_r$1),
        .leaf_r$2(rpc$leaf_r$2),
        .leaf_r$3(rpc$leaf_r$3),
        .leaf_g$0(rpc$leaf_g$0),
        .leaf_g$1(rpc$leaf_g$1),
        .leaf_g$2(rpc$leaf_g$2),
        .leaf_g$3(rpc$leaf_g$3),
        .leaf_b$0(rpc$leaf_b$0),
        .leaf_b$1(rpc$leaf_b$1),
        .leaf_b$2(rpc$leaf_b$2),
        .leaf_b$3(rpc$leaf_b$3),
        .leaf_a$0(rpc$leaf_a$0),
        .leaf_a$1(rpc$leaf_a$1),
        .leaf_a$2(rpc$leaf_a$2),
        .leaf_a$3(rpc$leaf_a$3),
        .leaf_valid$0(rpc$leaf_valid$0),
        .leaf_valid$1(rpc$leaf_valid$1),
        .leaf_valid$2(rpc$leaf_valid$2),
        .leaf_valid$3(rpc$leaf_valid$3),
        .first(rpc$first),
        .last(rpc$last),
        .done(rpc$done),
        .pixel_r(rpc$pixel_r),
        .pixel_g(rpc$pixel_g),
        .pixel_b(rpc$pixel_b),
        .pixel_a(rpc$pixel_a),
        .has_sample(rpc$has_sample)
    );
    
    // Update code
    reg  [31:0] pixel_r_pass;
    reg  [15:0] pixel_g_pass;
    reg  [15:0] pixel_b_pass;
    reg  [15:0] pixel_a_pass;
    reg  has_sample_pass;
    always @(*) begin
        regs$clock = clock;
        regs$host_write = host_write;
        regs$host_address = host_address;
        regs$host_data = host_data;
        lanes$offset = regs$q$0[('h20)+:(16)];
        lanes$line_last = regs$q$1[('h10)+:(16)];
        flags_line$last = regs$q$1[('h30)+:(16)];
        abc$ray_last = regs$q$2[('h0)+:(16)];
        abc$line_last = regs$q$2[('h10)+:(16)];
        control$clock = clock;
        control$host_write = host_write;
        control$host_address = host_address;
        control$host_data = host_data;
        lanes$clock = clock;
        abc$clock = clock;
        abc$host_write = host_write;
        abc$host_address = host_address;
        abc$host_data = host_data;
        rpc$clock = clock;
        flags_line$clock = clock;
        rpc_flags_q$clock = clock;
        cast_q$clock = clock;
        control$start = start;
        control$valid = valid;
        lanes$first = control$first;
        flags_q$0$clock = clock;
        flags_q$1$clock = clock;
        flags_q$2$clock = clock;
        flags_q$3$clock = clock;
        flags_q$4$clock = clock;
        flags_q$5$clock = clock;
        flags_q$6$clock = clock;
        flags_q$0$d = 32'(control$in_volume) | (32'(control$unit_valid) << 'h8) | (32'(control$unit_first) << 'h9) | (32'(control$unit_last) << 'ha) | (32'(control$unit_cast) << 'hb) | (32'(control$in_inner) << 'h10);
        flags_q$1$d = flags_q$0$q;
        flags_q$2$d = flags_q$1$q;
        flags_q$3$d = flags_q$2$q;
        flags_q$4$d = flags_q$3$q;
        flags_q$5$d = flags_q$4$q;
        flags_q$6$d = flags_q$5$q;
        flags_line$write_enable = 1'b1;
        flags_line$data_in = flags_q$6$q;
        leaf_flags = flags_q$6$q;
        if (gradients) begin
            leaf_flags = flags_line$data_out;
        end
        shade_flags_q$0$clock = clock;
        shade_flags_q$1$clock = clock;
        shade_flags_q$2$clock = clock;
        shade_flags_q$3$clock = clock;
        shade_flags_q$4$clock = clock;
        shade_flags_q$5$clock = clock;
        shade_flags_q$6$clock = clock;
        shade_flags_q$7$clock = clock;
        shade_flags_q$8$clock = clock;
        shade_flags_q$9$clock = clock;
        shade_flags_q$10$clock = clock;
        shade_flags_q$11$clock = clock;
        shade_flags_q$12$clock = clock;
        shade_flags_q$13$clock = clock;
        shade_flags_q$14$clock = clock;
        shade_flags_q$15$clock = clock;
        shade_flags_q$0$d = leaf_flags;
        shade_flags_q$1$d = shade_flags_q$0$q;
        shade_flags_q$2$d = shade_flags_q$1$q;
        shade_flags_q$3$d = shade_flags_q$2$q;
        shade_flags_q$4$d = shade_flags_q$3$q;
        shade_flags_q$5$d = shade_flags_q$4$q;
        shade_flags_q$6$d = shade_flags_q$5$q;
        shade_flags_q$7$d = shade_flags_q$6$q;
        shade_flags_q$8$d = shade_flags_q$7$q;
        shade_flags_q$9$d = shade_flags_q$8$q;
        shade_flags_q$10$d = shade_flags_q$9$q;
        shade_flags_q$11$d = shade_flags_q$10$q;
        shade_flags_q$12$d = shade_flags_q$11$q;
        shade_flags_q$13$d = shade_flags_q$12$q;
        shade_flags_q$14$d = shade_flags_q$13$q;
        shade_flags_q$15$d = shade_flags_q$14$q;
        rpc_flags_q$d = leaf_flags;
        if (shaded) begin
            rpc_flags_q$d = shade_flags_q$15$q;
        end
        abc$dx_neg = control$dx_neg;
        abc$dx_mag = control$dx_mag;
        abc$dy_neg = control$dy_neg;
        abc$dy_mag = control$dy_mag;
        lanes$cur$0 = cur$0;
        lanes$next$0 = next$0;
        lanes$wx$0 = control$wx$0;
        lanes$wy$0 = control$wy$0;
        abc$sample$0 = lanes$sample$0;
        leaf_q$0$clock = clock;
        leaf_valid_q$0$clock = clock;
        row$0 = (lanes$sample$0 >> frac) >> row_shift;
        opacity$0$clock = clock;
        opacity$0$host_write = host_write;
        opacity$0$host_address = host_address;
        opacity$0$host_data = host_data;
        opacity$0$address = row$0[('h0)+:(12)];
        leaf_valid_q$0$d = |(flags_q$6$q & lane_bit$0);
        leaf_q$0$d = 'h0;
        if (|(flags_q$6$q & lane_bit$0)) begin
            leaf_q$0$d = (lanes$sample$0 + half) >> frac;
        end
        index$0 = lanes$sample$0 >> frac;
        gx$0 = 'h0;
        gy$0 = 'h0;
        gz$0 = 'h0;
        if (gradients) begin
            index$0 = abc$centre$0 >> frac;
            gx$0 = abc$gx$0;
            gy$0 = abc$gy$0;
            gz$0 = abc$gz$0;
        end
        shade$0$clock = clock;
        shade$0$host_write = host_write;
        shade$0$host_address = host_address;
        shade$0$host_data = host_data;
        shade$0$value = index$0[('h0)+:(16)];
        shade$0$invalid = ~|(leaf_flags & lane_bit$0);
        shade$0$at_edge = ~|(leaf_flags & inner_bit$0);
        shade$0$gx_neg = gx$0['h1f];
        shade$0$gx_mag = gx$0;
        if (gx$0['h1f]) begin
            shade$0$gx_mag = ~gx$0 + 'h1;
        end
        shade$0$gy_neg = gy$0['h1f];
        shade$0$gy_mag = gy$0;
        if (gy$0['h1f]) begin
            shade$0$gy_mag = ~gy$0 + 'h1;
        end
        shade$0$gz_neg = gz$0['h1f];
        shade$0$gz_mag = gz$0;
        if (gz$0['h1f]) begin
            shade$0$gz_mag = ~gz$0 + 'h1;
        end
        rpc$leaf_r$0 = leaf_q$0$q;
        if (xray) begin
            rpc$leaf_r$0 = 'h0;
            if (leaf_valid_q$0$q) begin
                rpc$leaf_r$0 = opacity$0$data;
            end
        end
        rpc$leaf_g$0 = 'h0;
        rpc$leaf_b$0 = 'h0;
        rpc$leaf_a$0 = 'h0;
        rpc$leaf_valid$0 = leaf_valid_q$0$q;
        if (shaded) begin
            rpc$leaf_r$0 = shade$0$r;
            rpc$leaf_g$0 = shade$0$g;
            rpc$leaf_b$0 = shade$0$b;
            rpc$leaf_a$0 = shade$0$a;
            rpc$leaf_valid$0 = shade$0$valid;
        end
        lanes$cur$1 = cur$1;
        lanes$next$1 = next$1;
        lanes$wx$1 = control$wx$1;
        lanes$wy$1 = control$wy$1;
        abc$sample$1 = lanes$sample$1;
        leaf_q$1$clock = clock;
        leaf_valid_q$1$clock = clock;
        row$1 = (lanes$sample$1 >> frac) >> row_shift;
        opacity$1$clock = clock;
        opacity$1$host_write = host_write;
        opacity$1$host_address = host_address;
        opacity$1$host_data = host_data;
        opacity$1$address = row$1[('h0)+:(12)];
        leaf_valid_q$1$d = |(flags_q$6$q & lane_bit$1);
        leaf_q$1$d = 'h0;
        if (|(flags_q$6$q & lane_bit$1)) begin
            leaf_q$1$d = (lanes$sample$1 + half) >> frac;
        end
        index$1 = lanes$sample$1 >> frac;
        gx$1 = 'h0;
        gy$1 = 'h0;
        gz$1 = 'h0;
        if (gradients) begin
            index$1 = abc$centre$1 >> frac;
            gx$1 = abc$gx$1;
            gy$1 = abc$gy$1;
            gz$1 = abc$gz$1;
        end
        shade$1$clock = clock;
        shade$1$host_write = host_write;
        shade$1$host_address = host_address;
        shade$1$host_data = host_data;
        shade$1$value = index$1[('h0)+:(16)];
        shade$1$invalid = ~|(leaf_flags & lane_bit$1);
        shade$1$at_edge = ~|(leaf_flags & inner_bit$1);
        shade$1$gx_neg = gx$1['h1f];
        shade$1$gx_mag = gx$1;
        if (gx$1['h1f]) begin
            shade$1$gx_mag = ~gx$1 + 'h1;
        end
        shade$1$gy_neg = gy$1['h1f];
        shade$1$gy_mag = gy$1;
        if (gy$1['h1f]) begin
            shade$1$gy_mag = ~gy$1 + 'h1;
        end
        shade$1$gz_neg = gz$1['h1f];
        shade$1$gz_mag = gz$1;
        if (gz$1['h1f]) begin
            shade$1$gz_mag = ~gz$1 + 'h1;
        end
        rpc$leaf_r$1 = leaf_q$1$q;
        if (xray) begin
            rpc$leaf_r$1 = 'h0;
            if (leaf_valid_q$1$q) begin
                rpc$leaf_r$1 = opacity$1$data;
            end
        end
        rpc$leaf_g$1 = 'h0;
        rpc$leaf_b$1 = 'h0;
        rpc$leaf_a$1 = 'h0;
        rpc$leaf_valid$1 = leaf_valid_q$1$q;
        if (shaded) begin
            rpc$leaf_r$1 = shade$1$r;
            rpc$leaf_g$1 = shade$1$g;
            rpc$leaf_b$1 = shade$1$b;
            rpc$leaf_a$1 = shade$1$a;
            rpc$leaf_valid$1 = shade$1$valid;
        end
        lanes$cur$2 = cur$2;
        lanes$next$2 = next$2;
        lanes$wx$2 = control$wx$2;
        lanes$wy$2 = control$wy$2;
        abc$sample$2 = lanes$sample$2;
        leaf_q$2$clock = clock;
        leaf_valid_q$2$clock = clock;
        row$2 = (lanes$sample$2 >> frac) >> row_shift;
        opacity$2$clock = clock;
        opacity$2$host_write = host_write;
        opacity$2$host_address = host_address;
        opacity$2$host_data = host_data;
        opacity$2$address = row$2[('h0)+:(12)];
        leaf_valid_q$2$d = |(flags_q$6$q & lane_bit$2);
        leaf_q$2$d = 'h0;
        if (|(flags_q$6$q & lane_bit$2)) begin
            leaf_q$2$d = (lanes$sample$2 + half) >> frac;
        end
        index$2 = lanes$sample$2 >> frac;
        gx$2 = 'h0;
        gy$2 = 'h0;
        gz$2 = 'h0;
        if (gradients) begin
            index$2 = abc$centre$2 >> frac;
            gx$2 = abc$gx$2;
            gy$2 = abc$gy$2;
            gz$2 = abc$gz$2;
        end
        shade$2$clock = clock;
        shade$2$host_write = host_write;
        shade$2$host_address = host_address;
        shade$2$host_data = host_data;
        shade$2$value = index$2[('h0)+:(16)];
        shade$2$invalid = ~|(leaf_flags & lane_bit$2);
        shade$2$at_edge = ~|(leaf_flags & inner_bit$2);
        shade$2$gx_neg = gx$2['h1f];
        shade$2$gx_mag = gx$2;
        if (gx$2['h1f]) begin
            shade$2$gx_mag = ~gx$2 + 'h1;
        end
        shade$2$gy_neg = gy$2['h1f];
        shade$2$gy_mag = gy$2;
        if (gy$2['h1f]) begin
            shade$2$gy_mag = ~gy$2 + 'h1;
        end
        shade$2$gz_neg = gz$2['h1f];
        shade$2$gz_mag = gz$2;
        if (gz$2['h1f]) begin
            shade$2$gz_mag = ~gz$2 + 'h1;
        end
        rpc$leaf_r$2 = leaf_q$2$q;
        if (xray) begin
            rpc$leaf_r$2 = 'h0;
            if (leaf_valid_q$2$q) begin
                rpc$leaf_r$2 = opacity$2$data;
            end
        end
        rpc$leaf_g$2 = 'h0;
        rpc$leaf_b$2 = 'h0;
        rpc$leaf_a$2 = 'h0;
        rpc$leaf_valid$2 = leaf_valid_q$2$q;
        if (shaded) begin
            rpc$leaf_r$2 = shade$2$r;
            rpc$leaf_g$2 = shade$2$g;
            rpc$leaf_b$2 = shade$2$b;
            rpc$leaf_a$2 = shade$2$a;
            rpc$leaf_valid$2 = shade$2$valid;
        end
        lanes$cur$3 = cur$3;
        lanes$next$3 = next$3;
        lanes$wx$3 = control$wx$3;
        lanes$wy$3 = control$wy$3;
        abc$sample$3 = lanes$sample$3;
        leaf_q$3$clock = clock;
        leaf_valid_q$3$clock = clock;
        row$3 = (lanes$sample$3 >> frac) >> row_shift;
        opacity$3$clock = clock;
        opacity$3$host_write = host_write;
        opacity$3$host_address = host_address;
        opacity$3$host_data = host_data;
        opacity$3$address = row$3[('h0)+:(12)];
        leaf_valid_q$3$d = |(flags_q$6$q & lane_bit$3);
        leaf_q$3$d = 'h0;
        if (|(flags_q$6$q & lane_bit$3)) begin
            leaf_q$3$d = (lanes$sample$3 + half) >> frac;
        end
        index$3 = lanes$sample$3 >> frac;
        gx$3 = 'h0;
        gy$3 = 'h0;
        gz$3 = 'h0;
        if (gradients) begin
            index$3 = abc$centre$3 >> frac;
            gx$3 = abc$gx$3;
            gy$3 = abc$gy$3;
            gz$3 = abc$gz$3;
        end
        shade$3$clock = clock;
        shade$3$host_write = host_write;
        shade$3$host_address = host_address;
        shade$3$host_data = host_data;
        shade$3$value = index$3[('h0)+:(16)];
        shade$3$invalid = ~|(leaf_flags & lane_bit$3);
        shade$3$at_edge = ~|(leaf_flags & inner_bit$3);
        shade$3$gx_neg = gx$3['h1f];
        shade$3$gx_mag = gx$3;
        if (gx$3['h1f]) begin
            shade$3$gx_mag = ~gx$3 + 'h1;
        end
        shade$3$gy_neg = gy$3['h1f];
        shade$3$gy_mag = gy$3;
        if (gy$3['h1f]) begin
            shade$3$gy_mag = ~gy$3 + 'h1;
        end
        shade$3$gz_neg = gz$3['h1f];
        shade$3$gz_mag = gz$3;
        if (gz$3['h1f]) begin
            shade$3$gz_mag = ~gz$3 + 'h1;
        end
        rpc$leaf_r$3 = leaf_q$3$q;
        if (xray) begin
            rpc$leaf_r$3 = 'h0;
            if (leaf_valid_q$3$q) begin
                rpc$leaf_r$3 = opacity$3$data;
            end
        end
        rpc$leaf_g$3 = 'h0;
        rpc$leaf_b$3 = 'h0;
        rpc$leaf_a$3 = 'h0;
        rpc$leaf_valid$3 = leaf_valid_q$3$q;
        if (shaded) begin
            rpc$leaf_r$3 = shade$3$r;
            rpc$leaf_g$3 = shade$3$g;
            rpc$leaf_b$3 = shade$3$b;
            rpc$leaf_a$3 = shade$3$a;
            rpc$leaf_valid$3 = shade$3$valid;
        end
        rpc$first = rpc_flags_q$q['h9] & rpc_flags_q$q['h8];
        rpc$last = rpc_flags_q$q['ha] & rpc_flags_q$q['h8];
        cast_q$d = (cast_q$q << 'h1) | 8'(rpc_flags_q$q['hb]);
        pixel_cast = |(cast_q$q & cast_bit);
        done = rpc$done;
        pixel_r_pass = 'h0;
        pixel_g_pass = 'h0;
        pixel_b_pass = 'h0;
        pixel_a_pass = 'h0;
        has_sample_pass = 1'b0;
        if (pixel_cast) begin
            pixel_r_pass = rpc$pixel_r;
            pixel_g_pass = rpc$pixel_g;
            pixel_b_pass = rpc$pixel_b;
            pixel_a_pass = rpc$pixel_a;
            has_sample_pass = rpc$has_sample;
        end
        pixel_r = pixel_r_pass;
        pixel_g = pixel_g_pass;
        pixel_b = pixel_b_pass;
        pixel_a = pixel_a_pass;
        has_sample = has_sample_pass;
    end
    
endmodule // top$pipeline
module top$pipeline$cast_q(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$cast_q
module top$pipeline$flags_line(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  flip = 16'h1;
    localparam  longest_last = 16'h244;
    localparam  single = 1'b0;
    localparam  mask = 'hff0fff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [31:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [31:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [15:0] rd_flipped$d;
    wire  [15:0] rd_flipped$q;
    reg  rd_flipped$clock;
    reg  [31:0] one$d;
    wire  [31:0] one$q;
    reg  one$clock;
    
    // Local signals
    reg  [15:0] rd;
    reg  [15:0] next;
    
    // Sub module instances
    top$pipeline$flags_line$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$pipeline$flags_line$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$pipeline$flags_line$rd_flipped rd_flipped(
        .d(rd_flipped$d),
        .q(rd_flipped$q),
        .clock(rd_flipped$clock)
    );
    top$pipeline$flags_line$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    
    // Update code
    reg  [31:0] data_out_pass;
    always @(*) begin
        ptr$clock = clock;
        rd_flipped$clock = clock;
        one$clock = clock;
        ptr$d = ptr$q;
        rd_flipped$d = rd_flipped$q;
        one$d = one$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        rd = rd_flipped$q ^ flip;
        next = rd + 'h1;
        if ((rd >= last) | (rd >= longest_last)) begin
            next = 'h0;
        end
        rd_flipped$d = next ^ flip;
        ptr$d = rd;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & ~single;
        ram$read_address = rd;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        if (single | (last == 'h0)) begin
            data_out_pass = one$q;
        end
        else begin
            data_out_pass = ram$read_data;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$pipeline$flags_line
module top$pipeline$flags_line$one(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$flags_line$one
module top$pipeline$flags_line$ptr(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$flags_line$ptr
module top$pipeline$flags_line$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [19:0] mem[580:0];
    
    always @(posedge read_clock) begin
       read_data <= {8'd0, mem[read_address[9:0]][19:12], 4'd0, mem[read_address[9:0]][11:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[9:0]] <= {write_data[23:16], write_data[11:0]};
       end
    end
endmodule // top$pipeline$flags_line$ram
module top$pipeline$flags_line$rd_flipped(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$flags_line$rd_flipped
module top$pipeline$flags_q$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$flags_q$0
module top$pipeline$flags_q$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$flags_q$1
module top$pipeline$flags_q$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$flags_q$2
module top$pipeline$flags_q$3(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$flags_q$3
module top$pipeline$flags_q$4(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$flags_q$4
module top$pipeline$flags_q$5(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$flags_q$5
module top$pipeline$flags_q$6(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$flags_q$6
module top$pipeline$leaf_q$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$leaf_q$0
module top$pipeline$leaf_q$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$leaf_q$1
module top$pipeline$leaf_q$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$leaf_q$2
module top$pipeline$leaf_q$3(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$leaf_q$3
module top$pipeline$leaf_valid_q$0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$leaf_valid_q$0
module top$pipeline$leaf_valid_q$1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$leaf_valid_q$1
module top$pipeline$leaf_valid_q$2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$leaf_valid_q$2
module top$pipeline$leaf_valid_q$3(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$leaf_valid_q$3
module top$pipeline$opacity$0(clock,host_write,host_address,host_data,address,data);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  [11:0] address;
    output reg  [31:0] data;
    
    // Constant declarations
    localparam  base = 24'h40000;
    localparam  window = 24'h41000;
    
    // Stub signals
    reg  [11:0] ram$read_address;
    reg  ram$read_clock;
    wire  [31:0] ram$read_data;
    reg  [11:0] ram$write_address;
    reg  ram$write_clock;
    reg  [31:0] ram$write_data;
    reg  ram$write_enable;
    
    // Sub module instances
    top$pipeline$opacity$0$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    
    // Update code
    always @(*) begin
        ram$read_clock = clock;
        ram$write_clock = clock;
        ram$write_enable = host_write & (host_address >= base) & (host_address < window);
        ram$write_address = 12'(host_address - base);
        ram$write_data = 32'(host_data);
        ram$read_address = address;
        data = ram$read_data;
    end
    
endmodule // top$pipeline$opacity$0
module top$pipeline$opacity$0$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [11:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [11:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    (* ram_style = "distributed" *)
    reg [7:0] mem[1:0];
    
    always @(posedge read_clock) begin
       read_data <= {24'd0, mem[read_address[0:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[0:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$pipeline$opacity$0$ram
module top$pipeline$opacity$1(clock,host_write,host_address,host_data,address,data);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  [11:0] address;
    output reg  [31:0] data;
    
    // Constant declarations
    localparam  base = 24'h40000;
    localparam  window = 24'h41000;
    
    // Stub signals
    reg  [11:0] ram$read_address;
    reg  ram$read_clock;
    wire  [31:0] ram$read_data;
    reg  [11:0] ram$write_address;
    reg  ram$write_clock;
    reg  [31:0] ram$write_data;
    reg  ram$write_enable;
    
    // Sub module instances
    top$pipeline$opacity$1$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    
    // Update code
    always @(*) begin
        ram$read_clock = clock;
        ram$write_clock = clock;
        ram$write_enable = host_write & (host_address >= base) & (host_address < window);
        ram$write_address = 12'(host_address - base);
        ram$write_data = 32'(host_data);
        ram$read_address = address;
        data = ram$read_data;
    end
    
endmodule // top$pipeline$opacity$1
module top$pipeline$opacity$1$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [11:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [11:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    (* ram_style = "distributed" *)
    reg [7:0] mem[1:0];
    
    always @(posedge read_clock) begin
       read_data <= {24'd0, mem[read_address[0:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[0:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$pipeline$opacity$1$ram
module top$pipeline$opacity$2(clock,host_write,host_address,host_data,address,data);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  [11:0] address;
    output reg  [31:0] data;
    
    // Constant declarations
    localparam  base = 24'h40000;
    localparam  window = 24'h41000;
    
    // Stub signals
    reg  [11:0] ram$read_address;
    reg  ram$read_clock;
    wire  [31:0] ram$read_data;
    reg  [11:0] ram$write_address;
    reg  ram$write_clock;
    reg  [31:0] ram$write_data;
    reg  ram$write_enable;
    
    // Sub module instances
    top$pipeline$opacity$2$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    
    // Update code
    always @(*) begin
        ram$read_clock = clock;
        ram$write_clock = clock;
        ram$write_enable = host_write & (host_address >= base) & (host_address < window);
        ram$write_address = 12'(host_address - base);
        ram$write_data = 32'(host_data);
        ram$read_address = address;
        data = ram$read_data;
    end
    
endmodule // top$pipeline$opacity$2
module top$pipeline$opacity$2$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [11:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [11:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    (* ram_style = "distributed" *)
    reg [7:0] mem[1:0];
    
    always @(posedge read_clock) begin
       read_data <= {24'd0, mem[read_address[0:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[0:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$pipeline$opacity$2$ram
module top$pipeline$opacity$3(clock,host_write,host_address,host_data,address,data);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  [11:0] address;
    output reg  [31:0] data;
    
    // Constant declarations
    localparam  base = 24'h40000;
    localparam  window = 24'h41000;
    
    // Stub signals
    reg  [11:0] ram$read_address;
    reg  ram$read_clock;
    wire  [31:0] ram$read_data;
    reg  [11:0] ram$write_address;
    reg  ram$write_clock;
    reg  [31:0] ram$write_data;
    reg  ram$write_enable;
    
    // Sub module instances
    top$pipeline$opacity$3$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    
    // Update code
    always @(*) begin
        ram$read_clock = clock;
        ram$write_clock = clock;
        ram$write_enable = host_write & (host_address >= base) & (host_address < window);
        ram$write_address = 12'(host_address - base);
        ram$write_data = 32'(host_data);
        ram$read_address = address;
        data = ram$read_data;
    end
    
endmodule // top$pipeline$opacity$3
module top$pipeline$opacity$3$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [11:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [11:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    (* ram_style = "distributed" *)
    reg [7:0] mem[1:0];
    
    always @(posedge read_clock) begin
       read_data <= {24'd0, mem[read_address[0:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[0:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$pipeline$opacity$3$ram
module top$pipeline$regs(clock,host_write,host_address,host_data,q$0,q$1,q$2);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    output reg  [63:0] q$0;
    output reg  [63:0] q$1;
    output reg  [63:0] q$2;
    
    // Constant declarations
    localparam  address$0 = 24'h33;
    localparam  address$1 = 24'h36;
    localparam  address$2 = 24'h37;
    
    // Stub signals
    reg  [63:0] r$0$d;
    wire  [63:0] r$0$q;
    reg  r$0$clock;
    reg  [63:0] r$1$d;
    wire  [63:0] r$1$q;
    reg  r$1$clock;
    reg  [63:0] r$2$d;
    wire  [63:0] r$2$q;
    reg  r$2$clock;
    
    // Sub module instances
    top$pipeline$regs$r$0 r$0(
        .d(r$0$d),
        .q(r$0$q),
        .clock(r$0$clock)
    );
    top$pipeline$regs$r$1 r$1(
        .d(r$1$d),
        .q(r$1$q),
        .clock(r$1$clock)
    );
    top$pipeline$regs$r$2 r$2(
        .d(r$2$d),
        .q(r$2$q),
        .clock(r$2$clock)
    );
    
    // Update code
    always @(*) begin
        r$0$clock = clock;
        r$0$d = r$0$q;
        if (host_write & (host_address == address$0)) begin
            r$0$d = host_data;
        end
        q$0 = r$0$q;
        r$1$clock = clock;
        r$1$d = r$1$q;
        if (host_write & (host_address == address$1)) begin
            r$1$d = host_data;
        end
        q$1 = r$1$q;
        r$2$clock = clock;
        r$2$d = r$2$q;
        if (host_write & (host_address == address$2)) begin
            r$2$d = host_data;
        end
        q$2 = r$2$q;
    end
    
endmodule // top$pipeline$regs
module top$pipeline$regs$r$0(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$regs$r$0
module top$pipeline$regs$r$1(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$regs$r$1
module top$pipeline$regs$r$2(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$regs$r$2
module top$pipeline$rpc_flags_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$rpc_flags_q
module top$pipeline$shade_flags_q$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade_flags_q$0
module top$pipeline$shade_flags_q$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade_flags_q$1
module top$pipeline$shade_flags_q$10(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade_flags_q$10
module top$pipeline$shade_flags_q$11(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade_flags_q$11
module top$pipeline$shade_flags_q$12(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade_flags_q$12
module top$pipeline$shade_flags_q$13(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade_flags_q$13
module top$pipeline$shade_flags_q$14(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade_flags_q$14
module top$pipeline$shade_flags_q$15(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade_flags_q$15
module top$pipeline$shade_flags_q$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade_flags_q$2
module top$pipeline$shade_flags_q$3(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade_flags_q$3
module top$pipeline$shade_flags_q$4(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade_flags_q$4
module top$pipeline$shade_flags_q$5(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade_flags_q$5
module top$pipeline$shade_flags_q$6(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade_flags_q$6
module top$pipeline$shade_flags_q$7(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade_flags_q$7
module top$pipeline$shade_flags_q$8(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade_flags_q$8
module top$pipeline$shade_flags_q$9(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade_flags_q$9
