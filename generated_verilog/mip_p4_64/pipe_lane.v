module top$lanes$0(clock,now,beat_valid,value,x,y,pad,invalid,halo,sr,er,base_x,base_y,face,at_edge,dx_neg,dx_mag,dy_neg,dy_mag,g_from_left_xm,g_from_left_ym,g_from_left_zm,g_from_right_xp,g_from_right_yp,g_from_right_zp,g_to_right_xm,g_to_right_ym,g_to_right_zm,g_to_left_xp,g_to_left_yp,g_to_left_zp,t0s0,t0i1,t1s0,t1s1,t1i1,t1i2,t3s0,t3s1,t3i1,t3i2,t5s0,t5s1,t5s2,t5i1,t5i2,t5i3,t6s0,t6i1,t7s0,t7i1,t8s0,t8i1,t8il,res_beat,res_valid,res,px_valid,px_x,px_y,px_face);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] now;
    input wire  beat_valid;
    input wire  [15:0] value;
    input wire  [15:0] x;
    input wire  [15:0] y;
    input wire  pad;
    input wire  invalid;
    input wire  halo;
    input wire  sr;
    input wire  er;
    input wire  [15:0] base_x;
    input wire  [15:0] base_y;
    input wire  [2:0] face;
    input wire  at_edge;
    input wire  dx_neg;
    input wire  [15:0] dx_mag;
    input wire  dy_neg;
    input wire  [15:0] dy_mag;
    input wire  [15:0] g_from_left_xm;
    input wire  [15:0] g_from_left_ym;
    input wire  [15:0] g_from_left_zm;
    input wire  [15:0] g_from_right_xp;
    input wire  [15:0] g_from_right_yp;
    input wire  [15:0] g_from_right_zp;
    output reg  [15:0] g_to_right_xm;
    output reg  [15:0] g_to_right_ym;
    output reg  [15:0] g_to_right_zm;
    output reg  [15:0] g_to_left_xp;
    output reg  [15:0] g_to_left_yp;
    output reg  [15:0] g_to_left_zp;
    output reg  [63:0] t0s0;
    input wire  [63:0] t0i1;
    output reg  [63:0] t1s0;
    output reg  [63:0] t1s1;
    input wire  [63:0] t1i1;
    input wire  [63:0] t1i2;
    output reg  [63:0] t3s0;
    output reg  [63:0] t3s1;
    input wire  [63:0] t3i1;
    input wire  [63:0] t3i2;
    output reg  [63:0] t5s0;
    output reg  [63:0] t5s1;
    output reg  [63:0] t5s2;
    input wire  [63:0] t5i1;
    input wire  [63:0] t5i2;
    input wire  [63:0] t5i3;
    output reg  [63:0] t6s0;
    input wire  [63:0] t6i1;
    output reg  [63:0] t7s0;
    input wire  [63:0] t7i1;
    output reg  [63:0] t8s0;
    input wire  [63:0] t8i1;
    input wire  [63:0] t8il;
    output reg  res_beat;
    output reg  res_valid;
    output reg  [63:0] res;
    output reg  px_valid;
    output reg  [15:0] px_x;
    output reg  [15:0] px_y;
    output reg  [2:0] px_face;
    
    // Constant declarations
    localparam  use_gradient = 1'b0;
    localparam  hops0 = 2'b1;
    localparam  off0 = 16'hfc02;
    localparam  hops1 = 2'b10;
    localparam  off1 = 16'hfc03;
    localparam  off2 = 16'hfc02;
    localparam  hops3 = 2'b10;
    localparam  off3 = 16'hfbf3;
    localparam  off4 = 16'hfc11;
    localparam  hops5 = 2'b11;
    localparam  off5 = 16'hfbf4;
    localparam  hops6 = 2'b1;
    localparam  off6 = 16'hfbf3;
    localparam  hops7 = 2'b1;
    localparam  off7 = 16'hfc12;
    localparam  hops8 = 2'b1;
    localparam  off8 = 16'hfc13;
    localparam  left8 = 1'b1;
    localparam  p_mask = 16'h3;
    localparam  nx_last = 16'h3f;
    localparam  ny_last = 16'h3f;
    localparam  reset = 64'h0;
    localparam  r_mask = 64'hffff;
    localparam  gba_mask = 64'hffff;
    
    // Stub signals
    reg  abc$clock;
    reg  [15:0] abc$now;
    reg  abc$valid;
    reg  [15:0] abc$value;
    reg  [15:0] abc$x;
    reg  [15:0] abc$y;
    reg  abc$pad;
    reg  abc$invalid;
    reg  abc$dx_neg;
    reg  [15:0] abc$dx_mag;
    reg  abc$dy_neg;
    reg  [15:0] abc$dy_mag;
    reg  abc$sr;
    reg  abc$er;
    reg  abc$at_edge;
    reg  [2:0] abc$face;
    reg  [15:0] abc$base_x;
    reg  [15:0] abc$base_y;
    reg  [15:0] abc$from_left_xm;
    reg  [15:0] abc$from_left_ym;
    reg  [15:0] abc$from_left_zm;
    reg  [15:0] abc$from_right_xp;
    reg  [15:0] abc$from_right_yp;
    reg  [15:0] abc$from_right_zp;
    wire  [15:0] abc$to_right_xm = 'h0;
    wire  [15:0] abc$to_right_ym = 'h0;
    wire  [15:0] abc$to_right_zm = 'h0;
    wire  [15:0] abc$to_left_xp = 'h0;
    wire  [15:0] abc$to_left_yp = 'h0;
    wire  [15:0] abc$to_left_zp = 'h0;
    wire  abc$o_valid = 'h0;
    wire  [15:0] abc$o_value = 'h0;
    wire  [15:0] abc$o_x = 'h0;
    wire  [15:0] abc$o_y = 'h0;
    wire  abc$o_pad = 'h0;
    wire  abc$o_invalid = 'h0;
    wire  abc$o_dx_neg = 'h0;
    wire  [15:0] abc$o_dx_mag = 'h0;
    wire  abc$o_dy_neg = 'h0;
    wire  [15:0] abc$o_dy_mag = 'h0;
    wire  abc$o_sr = 'h0;
    wire  abc$o_er = 'h0;
    wire  abc$o_edge = 'h0;
    wire  [2:0] abc$o_face = 'h0;
    wire  [15:0] abc$o_base_x = 'h0;
    wire  [15:0] abc$o_base_y = 'h0;
    wire  abc$gx_neg = 'h0;
    wire  [15:0] abc$gx_mag = 'h0;
    wire  abc$gy_neg = 'h0;
    wire  [15:0] abc$gy_mag = 'h0;
    wire  abc$gz_neg = 'h0;
    wire  [15:0] abc$gz_mag = 'h0;
    reg  shader$clock;
    reg  [15:0] shader$value;
    reg  shader$invalid;
    reg  shader$at_edge;
    reg  shader$gx_neg;
    reg  [15:0] shader$gx_mag;
    reg  shader$gy_neg;
    reg  [15:0] shader$gy_mag;
    reg  shader$gz_neg;
    reg  [15:0] shader$gz_mag;
    wire  [15:0] shader$r;
    wire  [15:0] shader$g;
    wire  [15:0] shader$b;
    wire  [15:0] shader$a;
    wire  shader$valid;
    reg  [15:0] ring0$read_address;
    reg  ring0$read_clock;
    wire  [63:0] ring0$read_data;
    reg  [15:0] ring0$write_address;
    reg  ring0$write_clock;
    reg  [63:0] ring0$write_data;
    reg  ring0$write_enable;
    reg  [63:0] f0_1$d;
    wire  [63:0] f0_1$q;
    reg  f0_1$clock;
    reg  [63:0] prev0$d;
    wire  [63:0] prev0$q;
    reg  prev0$clock;
    reg  [15:0] ring1$read_address;
    reg  ring1$read_clock;
    wire  [63:0] ring1$read_data;
    reg  [15:0] ring1$write_address;
    reg  ring1$write_clock;
    reg  [63:0] ring1$write_data;
    reg  ring1$write_enable;
    reg  [63:0] f1_1$d;
    wire  [63:0] f1_1$q;
    reg  f1_1$clock;
    reg  [63:0] f1_2$d;
    wire  [63:0] f1_2$q;
    reg  f1_2$clock;
    reg  [63:0] prev1$d;
    wire  [63:0] prev1$q;
    reg  prev1$clock;
    reg  [15:0] ring2$read_address;
    reg  ring2$read_clock;
    wire  [63:0] ring2$read_data;
    reg  [15:0] ring2$write_address;
    reg  ring2$write_clock;
    reg  [63:0] ring2$write_data;
    reg  ring2$write_enable;
    reg  [63:0] prev2$d;
    wire  [63:0] prev2$q;
    reg  prev2$clock;
    reg  [15:0] ring3$read_address;
    reg  ring3$read_clock;
    wire  [63:0] ring3$read_data;
    reg  [15:0] ring3$write_address;
    reg  ring3$write_clock;
    reg  [63:0] ring3$write_data;
    reg  ring3$write_enable;
    reg  [63:0] f3_1$d;
    wire  [63:0] f3_1$q;
    reg  f3_1$clock;
    reg  [63:0] f3_2$d;
    wire  [63:0] f3_2$q;
    reg  f3_2$clock;
    reg  [63:0] prev3$d;
    wire  [63:0] prev3$q;
    reg  prev3$clock;
    reg  [15:0] ring4$read_address;
    reg  ring4$read_clock;
    wire  [63:0] ring4$read_data;
    reg  [15:0] ring4$write_address;
    reg  ring4$write_clock;
    reg  [63:0] ring4$write_data;
    reg  ring4$write_enable;
    reg  [63:0] prev4$d;
    wire  [63:0] prev4$q;
    reg  prev4$clock;
    reg  [15:0] ring5$read_address;
    reg  ring5$read_clock;
    wire  [63:0] ring5$read_data;
    reg  [15:0] ring5$write_address;
    reg  ring5$write_clock;
    reg  [63:0] ring5$write_data;
    reg  ring5$write_enable;
    reg  [63:0] f5_1$d;
    wire  [63:0] f5_1$q;
    reg  f5_1$clock;
    reg  [63:0] f5_2$d;
    wire  [63:0] f5_2$q;
    reg  f5_2$clock;
    reg  [63:0] f5_3$d;
    wire  [63:0] f5_3$q;
    reg  f5_3$clock;
    reg  [63:0] prev5$d;
    wire  [63:0] prev5$q;
    reg  prev5$clock;
    reg  [15:0] ring6$read_address;
    reg  ring6$read_clock;
    wire  [63:0] ring6$read_data;
    reg  [15:0] ring6$write_address;
    reg  ring6$write_clock;
    reg  [63:0] ring6$write_data;
    reg  ring6$write_enable;
    reg  [63:0] f6_1$d;
    wire  [63:0] f6_1$q;
    reg  f6_1$clock;
    reg  [63:0] prev6$d;
    wire  [63:0] prev6$q;
    reg  prev6$clock;
    reg  [15:0] ring7$read_address;
    reg  ring7$read_clock;
    wire  [63:0] ring7$read_data;
    reg  [15:0] ring7$write_address;
    reg  ring7$write_clock;
    reg  [63:0] ring7$write_data;
    reg  ring7$write_enable;
    reg  [63:0] f7_1$d;
    wire  [63:0] f7_1$q;
    reg  f7_1$clock;
    reg  [63:0] prev7$d;
    wire  [63:0] prev7$q;
    reg  prev7$clock;
    reg  [15:0] ring8$read_address;
    reg  ring8$read_clock;
    wire  [63:0] ring8$read_data;
    reg  [15:0] ring8$write_address;
    reg  ring8$write_clock;
    reg  [63:0] ring8$write_data;
    reg  ring8$write_enable;
    reg  [63:0] f8_1$d;
    wire  [63:0] f8_1$q;
    reg  f8_1$clock;
    reg  [63:0] prev8$d;
    wire  [63:0] prev8$q;
    reg  prev8$clock;
    reg  [63:0] f8l$d;
    wire  [63:0] f8l$q;
    reg  f8l$clock;
    reg  bilinear$clock;
    reg  [31:0] bilinear$c00$0;
    reg  [31:0] bilinear$c00$1;
    reg  [31:0] bilinear$c00$2;
    reg  [31:0] bilinear$c00$3;
    reg  [31:0] bilinear$c10$0;
    reg  [31:0] bilinear$c10$1;
    reg  [31:0] bilinear$c10$2;
    reg  [31:0] bilinear$c10$3;
    reg  [31:0] bilinear$c01$0;
    reg  [31:0] bilinear$c01$1;
    reg  [31:0] bilinear$c01$2;
    reg  [31:0] bilinear$c01$3;
    reg  [31:0] bilinear$c11$0;
    reg  [31:0] bilinear$c11$1;
    reg  [31:0] bilinear$c11$2;
    reg  [31:0] bilinear$c11$3;
    reg  [15:0] bilinear$wx;
    reg  [15:0] bilinear$wy;
    wire  [31:0] bilinear$out$0;
    wire  [31:0] bilinear$out$1;
    wire  [31:0] bilinear$out$2;
    wire  [31:0] bilinear$out$3;
    reg  compositor$clock;
    reg  [31:0] compositor$acc_r;
    reg  [15:0] compositor$acc_g;
    reg  [15:0] compositor$acc_b;
    reg  [15:0] compositor$acc_a;
    reg  [31:0] compositor$new_r;
    reg  [15:0] compositor$new_g;
    reg  [15:0] compositor$new_b;
    reg  [15:0] compositor$new_a;
    reg  compositor$new_valid;
    wire  [31:0] compositor$out_r;
    wire  [15:0] compositor$out_g;
    wire  [15:0] compositor$out_b;
    wire  [15:0] compositor$out_a;
    reg  v_q$0$d;
    wire  v_q$0$q;
    reg  v_q$0$clock;
    reg  v_q$1$d;
    wire  v_q$1$q;
    reg  v_q$1$clock;
    reg  v_q$2$d;
    wire  v_q$2$q;
    reg  v_q$2$clock;
    reg  v_q$3$d;
    wire  v_q$3$q;
    reg  v_q$3$clock;
    reg  er_q$0$d;
    wire  er_q$0$q;
    reg  er_q$0$clock;
    reg  er_q$1$d;
    wire  er_q$1$q;
    reg  er_q$1$clock;
    reg  er_q$2$d;
    wire  er_q$2$q;
    reg  er_q$2$clock;
    reg  er_q$3$d;
    wire  er_q$3$q;
    reg  er_q$3$clock;
    reg  pad_q$0$d;
    wire  pad_q$0$q;
    reg  pad_q$0$clock;
    reg  pad_q$1$d;
    wire  pad_q$1$q;
    reg  pad_q$1$clock;
    reg  pad_q$2$d;
    wire  pad_q$2$q;
    reg  pad_q$2$clock;
    reg  pad_q$3$d;
    wire  pad_q$3$q;
    reg  pad_q$3$clock;
    reg  [15:0] bx_q$0$d;
    wire  [15:0] bx_q$0$q;
    reg  bx_q$0$clock;
    reg  [15:0] bx_q$1$d;
    wire  [15:0] bx_q$1$q;
    reg  bx_q$1$clock;
    reg  [15:0] bx_q$2$d;
    wire  [15:0] bx_q$2$q;
    reg  bx_q$2$clock;
    reg  [15:0] bx_q$3$d;
    wire  [15:0] bx_q$3$q;
    reg  bx_q$3$clock;
    reg  [15:0] by_q$0$d;
    wire  [15:0] by_q$0$q;
    reg  by_q$0$clock;
    reg  [15:0] by_q$1$d;
    wire  [15:0] by_q$1$q;
    reg  by_q$1$clock;
    reg  [15:0] by_q$2$d;
    wire  [15:0] by_q$2$q;
    reg  by_q$2$clock;
    reg  [15:0] by_q$3$d;
    wire  [15:0] by_q$3$q;
    reg  by_q$3$clock;
    reg  [2:0] face_q$0$d;
    wire  [2:0] face_q$0$q;
    reg  face_q$0$clock;
    reg  [2:0] face_q$1$d;
    wire  [2:0] face_q$1$q;
    reg  face_q$1$clock;
    reg  [2:0] face_q$2$d;
    wire  [2:0] face_q$2$q;
    reg  face_q$2$clock;
    reg  [2:0] face_q$3$d;
    wire  [2:0] face_q$3$q;
    reg  face_q$3$clock;
    reg  [15:0] x_q$d;
    wire  [15:0] x_q$q;
    reg  x_q$clock;
    reg  [15:0] y_q$d;
    wire  [15:0] y_q$q;
    reg  y_q$clock;
    reg  sr_q$d;
    wire  sr_q$q;
    reg  sr_q$clock;
    reg  dxn_q$d;
    wire  dxn_q$q;
    reg  dxn_q$clock;
    reg  [15:0] dxm_q$d;
    wire  [15:0] dxm_q$q;
    reg  dxm_q$clock;
    reg  dyn_q$d;
    wire  dyn_q$q;
    reg  dyn_q$clock;
    reg  [15:0] dym_q$d;
    wire  [15:0] dym_q$q;
    reg  dym_q$clock;
    reg  [15:0] s_r$0$d;
    wire  [15:0] s_r$0$q;
    reg  s_r$0$clock;
    reg  [15:0] s_r$1$d;
    wire  [15:0] s_r$1$q;
    reg  s_r$1$clock;
    reg  [15:0] s_g$0$d;
    wire  [15:0] s_g$0$q;
    reg  s_g$0$clock;
    reg  [15:0] s_g$1$d;
    wire  [15:0] s_g$1$q;
    reg  s_g$1$clock;
    reg  [15:0] s_b$0$d;
    wire  [15:0] s_b$0$q;
    reg  s_b$0$clock;
    reg  [15:0] s_b$1$d;
    wire  [15:0] s_b$1$q;
    reg  s_b$1$clock;
    reg  [15:0] s_a$0$d;
    wire  [15:0] s_a$0$q;
    reg  s_a$0$clock;
    reg  [15:0] s_a$1$d;
    wire  [15:0] s_a$1$q;
    reg  s_a$1$clock;
    reg  s_v$0$d;
    wire  s_v$0$q;
    reg  s_v$0$clock;
    reg  s_v$1$d;
    wire  s_v$1$q;
    reg  s_v$1$clock;
    
    // Local signals
    reg  st_valid;
    reg  [15:0] st_value;
    reg  [15:0] st_x;
    reg  [15:0] st_y;
    reg  st_pad;
    reg  st_invalid;
    reg  st_sr;
    reg  st_er;
    reg  st_edge;
    reg  [2:0] st_face;
    reg  [15:0] st_bx;
    reg  [15:0] st_by;
    reg  st_dxn;
    reg  [15:0] st_dxm;
    reg  st_dyn;
    reg  [15:0] st_dym;
    reg  [63:0] s0;
    reg  [63:0] a0;
    reg  [63:0] s1;
    reg  [63:0] a1;
    reg  [63:0] s2;
    reg  [63:0] a2;
    reg  [63:0] s3;
    reg  [63:0] a3;
    reg  [63:0] s4;
    reg  [63:0] a4;
    reg  [63:0] s5;
    reg  [63:0] a5;
    reg  [63:0] s6;
    reg  [63:0] a6;
    reg  [63:0] s7;
    reg  [63:0] a7;
    reg  [63:0] s8;
    reg  [63:0] a8;
    reg  first;
    reg  last;
    reg  [63:0] c00;
    reg  [63:0] c10;
    reg  [63:0] c01;
    reg  [63:0] c11;
    reg  x_out;
    reg  y_out;
    
    // Sub module instances
    top$lanes$0$shader shader(
        .clock(shader$clock),
        .value(shader$value),
        .invalid(shader$invalid),
        .at_edge(shader$at_edge),
        .gx_neg(shader$gx_neg),
        .gx_mag(shader$gx_mag),
        .gy_neg(shader$gy_neg),
        .gy_mag(shader$gy_mag),
        .gz_neg(shader$gz_neg),
        .gz_mag(shader$gz_mag),
        .r(shader$r),
        .g(shader$g),
        .b(shader$b),
        .a(shader$a),
        .valid(shader$valid)
    );
    top$lanes$0$ring0 ring0(
        .read_address(ring0$read_address),
        .read_clock(ring0$read_clock),
        .read_data(ring0$read_data),
        .write_address(ring0$write_address),
        .write_clock(ring0$write_clock),
        .write_data(ring0$write_data),
        .write_enable(ring0$write_enable)
    );
    top$lanes$0$f0_1 f0_1(
        .d(f0_1$d),
        .q(f0_1$q),
        .clock(f0_1$clock)
    );
    top$lanes$0$prev0 prev0(
        .d(prev0$d),
        .q(prev0$q),
        .clock(prev0$clock)
    );
    top$lanes$0$ring1 ring1(
        .read_address(ring1$read_address),
        .read_clock(ring1$read_clock),
        .read_data(ring1$read_data),
        .write_address(ring1$write_address),
        .write_clock(ring1$write_clock),
        .write_data(ring1$write_data),
        .write_enable(ring1$write_enable)
    );
    top$lanes$0$f1_1 f1_1(
        .d(f1_1$d),
        .q(f1_1$q),
        .clock(f1_1$clock)
    );
    top$lanes$0$f1_2 f1_2(
        .d(f1_2$d),
        .q(f1_2$q),
        .clock(f1_2$clock)
    );
    top$lanes$0$prev1 prev1(
        .d(prev1$d),
        .q(prev1$q),
        .clock(prev1$clock)
    );
    top$lanes$0$ring2 ring2(
        .read_address(ring2$read_address),
        .read_clock(ring2$read_clock),
        .read_data(ring2$read_data),
        .write_address(ring2$write_address),
        .write_clock(ring2$write_clock),
        .write_data(ring2$write_data),
        .write_enable(ring2$write_enable)
    );
    top$lanes$0$prev2 prev2(
        .d(prev2$d),
        .q(prev2$q),
        .clock(prev2$clock)
    );
    top$lanes$0$ring3 ring3(
        .read_address(ring3$read_address),
        .read_clock(ring3$read_clock),
        .read_data(ring3$read_data),
        .write_address(ring3$write_address),
        .write_clock(ring3$write_clock),
        .write_data(ring3$write_data),
        .write_enable(ring3$write_enable)
    );
    top$lanes$0$f3_1 f3_1(
        .d(f3_1$d),
        .q(f3_1$q),
        .clock(f3_1$clock)
    );
    top$lanes$0$f3_2 f3_2(
        .d(f3_2$d),
        .q(f3_2$q),
        .clock(f3_2$clock)
    );
    top$lanes$0$prev3 prev3(
        .d(prev3$d),
        .q(prev3$q),
        .clock(prev3$clock)
    );
    top$lanes$0$ring4 ring4(
        .read_address(ring4$read_address),
        .read_clock(ring4$read_clock),
        .read_data(ring4$read_data),
        .write_address(ring4$write_address),
        .write_clock(ring4$write_clock),
        .write_data(ring4$write_data),
        .write_enable(ring4$write_enable)
    );
    top$lanes$0$prev4 prev4(
        .d(prev4$d),
        .q(prev4$q),
        .clock(prev4$clock)
    );
    top$lanes$0$ring5 ring5(
        .read_address(ring5$read_address),
        .read_clock(ring5$read_clock),
        .read_data(ring5$read_data),
        .write_address(ring5$write_address),
        .write_clock(ring5$write_clock),
        .write_data(ring5$write_data),
        .write_enable(ring5$write_enable)
    );
    top$lanes$0$f5_1 f5_1(
        .d(f5_1$d),
        .q(f5_1$q),
        .clock(f5_1$clock)
    );
    top$lanes$0$f5_2 f5_2(
        .d(f5_2$d),
        .q(f5_2$q),
        .clock(f5_2$clock)
    );
    top$lanes$0$f5_3 f5_3(
        .d(f5_3$d),
        .q(f5_3$q),
        .clock(f5_3$clock)
    );
    top$lanes$0$prev5 prev5(
        .d(prev5$d),
        .q(prev5$q),
        .clock(prev5$clock)
    );
    top$lanes$0$ring6 ring6(
        .read_address(ring6$read_address),
        .read_clock(ring6$read_clock),
        .read_data(ring6$read_data),
        .write_address(ring6$write_address),
        .write_clock(ring6$write_clock),
        .write_data(ring6$write_data),
        .write_enable(ring6$write_enable)
    );
    top$lanes$0$f6_1 f6_1(
        .d(f6_1$d),
        .q(f6_1$q),
        .clock(f6_1$clock)
    );
    top$lanes$0$prev6 prev6(
        .d(prev6$d),
        .q(prev6$q),
        .clock(prev6$clock)
    );
    top$lanes$0$ring7 ring7(
        .read_address(ring7$read_address),
        .read_clock(ring7$read_clock),
        .read_data(ring7$read_data),
        .write_address(ring7$write_address),
        .write_clock(ring7$write_clock),
        .write_data(ring7$write_data),
        .write_enable(ring7$write_enable)
    );
    top$lanes$0$f7_1 f7_1(
        .d(f7_1$d),
        .q(f7_1$q),
        .clock(f7_1$clock)
    );
    top$lanes$0$prev7 prev7(
        .d(prev7$d),
        .q(prev7$q),
        .clock(prev7$clock)
    );
    top$lanes$0$ring8 ring8(
        .read_address(ring8$read_address),
        .read_clock(ring8$read_clock),
        .read_data(ring8$read_data),
        .write_address(ring8$write_address),
        .write_clock(ring8$write_clock),
        .write_data(ring8$write_data),
        .write_enable(ring8$write_enable)
    );
    top$lanes$0$f8_1 f8_1(
        .d(f8_1$d),
        .q(f8_1$q),
        .clock(f8_1$clock)
    );
    top$lanes$0$prev8 prev8(
        .d(prev8$d),
        .q(prev8$q),
        .clock(prev8$clock)
    );
    top$lanes$0$f8l f8l(
        .d(f8l$d),
        .q(f8l$q),
        .clock(f8l$clock)
    );
    top$lanes$0$bilinear bilinear(
        .clock(bilinear$clock),
        .c00$0(bilinear$c00$0),
        .c00$1(bilinear$c00$1),
        .c00$2(bilinear$c00$2),
        .c00$3(bilinear$c00$3),
        .c10$0(bilinear$c10$0),
        .c10$1(bilinear$c10$1),
        .c10$2(bilinear$c10$2),
        .c10$3(bilinear$c10$3),
        .c01$0(bilinear$c01$0),
        .c01$1(bilinear$c01$1),
        .c01$2(bilinear$c01$2),
        .c01$3(bilinear$c01$3),
        .c11$0(bilinear$c11$0),
        .c11$1(bilinear$c11$1),
        .c11$2(bilinear$c11$2),
        .c11$3(bilinear$c11$3),
        .wx(bilinear$wx),
        .wy(bilinear$wy),
        .out$0(bilinear$out$0),
        .out$1(bilinear$out$1),
        .out$2(bilinear$out$2),
        .out$3(bilinear$out$3)
    );
    top$lanes$0$compositor compositor(
        .clock(compositor$clock),
        .acc_r(compositor$acc_r),
        .acc_g(compositor$acc_g),
        .acc_b(compositor$acc_b),
        .acc_a(compositor$acc_a),
        .new_r(compositor$new_r),
        .new_g(compositor$new_g),
        .new_b(compositor$new_b),
        .new_a(compositor$new_a),
        .new_valid(compositor$new_valid),
        .out_r(compositor$out_r),
        .out_g(compositor$out_g),
        .out_b(compositor$out_b),
        .out_a(compositor$out_a)
    );
    top$lanes$0$v_q$0 v_q$0(
        .d(v_q$0$d),
        .q(v_q$0$q),
        .clock(v_q$0$clock)
    );
    top$lanes$0$v_q$1 v_q$1(
        .d(v_q$1$d),
        .q(v_q$1$q),
        .clock(v_q$1$clock)
    );
    top$lanes$0$v_q$2 v_q$2(
        .d(v_q$2$d),
        .q(v_q$2$q),
        .clock(v_q$2$clock)
    );
    top$lanes$0$v_q$3 v_q$3(
        .d(v_q$3$d),
        .q(v_q$3$q),
        .clock(v_q$3$clock)
    );
    top$lanes$0$er_q$0 er_q$0(
        .d(er_q$0$d),
        .q(er_q$0$q),
        .clock(er_q$0$clock)
    );
    top$lanes$0$er_q$1 er_q$1(
        .d(er_q$1$d),
        .q(er_q$1$q),
        .clock(er_q$1$clock)
    );
    top$lanes$0$er_q$2 er_q$2(
        .d(er_q$2$d),
        .q(er_q$2$q),
        .clock(er_q$2$clock)
    );
    top$lanes$0$er_q$3 er_q$3(
        .d(er_q$3$d),
        .q(er_q$3$q),
        .clock(er_q$3$clock)
    );
    top$lanes$0$pad_q$0 pad_q$0(
        .d(pad_q$0$d),
        .q(pad_q$0$q),
        .clock(pad_q$0$clock)
    );
    top$lanes$0$pad_q$1 pad_q$1(
        .d(pad_q$1$d),
        .q(pad_q$1$q),
        .clock(pad_q$1$clock)
    );
    top$lanes$0$pad_q$2 pad_q$2(
        .d(pad_q$2$d),
        .q(pad_q$2$q),
        .clock(pad_q$2$clock)
    );
    top$lanes$0$pad_q$3 pad_q$3(
        .d(pad_q$3$d),
        .q(pad_q$3$q),
        .clock(pad_q$3$clock)
    );
    top$lanes$0$bx_q$0 bx_q$0(
        .d(bx_q$0$d),
        .q(bx_q$0$q),
        .clock(bx_q$0$clock)
    );
    top$lanes$0$bx_q$1 bx_q$1(
        .d(bx_q$1$d),
        .q(bx_q$1$q),
        .clock(bx_q$1$clock)
    );
    top$lanes$0$bx_q$2 bx_q$2(
        .d(bx_q$2$d),
        .q(bx_q$2$q),
        .clock(bx_q$2$clock)
    );
    top$lanes$0$bx_q$3 bx_q$3(
        .d(bx_q$3$d),
        .q(bx_q$3$q),
        .clock(bx_q$3$clock)
    );
    top$lanes$0$by_q$0 by_q$0(
        .d(by_q$0$d),
        .q(by_q$0$q),
        .clock(by_q$0$clock)
    );
    top$lanes$0$by_q$1 by_q$1(
        .d(by_q$1$d),
        .q(by_q$1$q),
        .clock(by_q$1$clock)
    );
    top$lanes$0$by_q$2 by_q$2(
        .d(by_q$2$d),
        .q(by_q$2$q),
        .clock(by_q$2$clock)
    );
    top$lanes$0$by_q$3 by_q$3(
        .d(by_q$3$d),
        .q(by_q$3$q),
        .clock(by_q$3$clock)
    );
    top$lanes$0$face_q$0 face_q$0(
        .d(face_q$0$d),
        .q(face_q$0$q),
        .clock(face_q$0$clock)
    );
    top$lanes$0$face_q$1 face_q$1(
        .d(face_q$1$d),
        .q(face_q$1$q),
        .clock(face_q$1$clock)
    );
    top$lanes$0$face_q$2 face_q$2(
        .d(face_q$2$d),
        .q(face_q$2$q),
        .clock(face_q$2$clock)
    );
    top$lanes$0$face_q$3 face_q$3(
        .d(face_q$3$d),
        .q(face_q$3$q),
        .clock(face_q$3$clock)
    );
    top$lanes$0$x_q x_q(
        .d(x_q$d),
        .q(x_q$q),
        .clock(x_q$clock)
    );
    top$lanes$0$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    top$lanes$0$sr_q sr_q(
        .d(sr_q$d),
        .q(sr_q$q),
        .clock(sr_q$clock)
    );
    top$lanes$0$dxn_q dxn_q(
        .d(dxn_q$d),
        .q(dxn_q$q),
        .clock(dxn_q$clock)
    );
    top$lanes$0$dxm_q dxm_q(
        .d(dxm_q$d),
        .q(dxm_q$q),
        .clock(dxm_q$clock)
    );
    top$lanes$0$dyn_q dyn_q(
        .d(dyn_q$d),
        .q(dyn_q$q),
        .clock(dyn_q$clock)
    );
    top$lanes$0$dym_q dym_q(
        .d(dym_q$d),
        .q(dym_q$q),
        .clock(dym_q$clock)
    );
    top$lanes$0$s_r$0 s_r$0(
        .d(s_r$0$d),
        .q(s_r$0$q),
        .clock(s_r$0$clock)
    );
    top$lanes$0$s_r$1 s_r$1(
        .d(s_r$1$d),
        .q(s_r$1$q),
        .clock(s_r$1$clock)
    );
    top$lanes$0$s_g$0 s_g$0(
        .d(s_g$0$d),
        .q(s_g$0$q),
        .clock(s_g$0$clock)
    );
    top$lanes$0$s_g$1 s_g$1(
        .d(s_g$1$d),
        .q(s_g$1$q),
        .clock(s_g$1$clock)
    );
    top$lanes$0$s_b$0 s_b$0(
        .d(s_b$0$d),
        .q(s_b$0$q),
        .clock(s_b$0$clock)
    );
    top$lanes$0$s_b$1 s_b$1(
        .d(s_b$1$d),
        .q(s_b$1$q),
        .clock(s_b$1$clock)
    );
    top$lanes$0$s_a$0 s_a$0(
        .d(s_a$0$d),
        .q(s_a$0$q),
        .clock(s_a$0$clock)
    );
    top$lanes$0$s_a$1 s_a$1(
        .d(s_a$1$d),
        .q(s_a$1$q),
        .clock(s_a$1$clock)
    );
    top$lanes$0$s_v$0 s_v$0(
        .d(s_v$0$d),
        .q(s_v$0$q),
        .clock(s_v$0$clock)
    );
    top$lanes$0$s_v$1 s_v$1(
        .d(s_v$1$d),
        .q(s_v$1$q),
        .clock(s_v$1$clock)
    );
    
    // Update code
    always @(*) begin
        x_q$clock = clock;
        y_q$clock = clock;
        sr_q$clock = clock;
        dxn_q$clock = clock;
        dxm_q$clock = clock;
        dyn_q$clock = clock;
        dym_q$clock = clock;
        f0_1$clock = clock;
        prev0$clock = clock;
        f1_1$clock = clock;
        f1_2$clock = clock;
        prev1$clock = clock;
        prev2$clock = clock;
        f3_1$clock = clock;
        f3_2$clock = clock;
        prev3$clock = clock;
        prev4$clock = clock;
        f5_1$clock = clock;
        f5_2$clock = clock;
        f5_3$clock = clock;
        prev5$clock = clock;
        f6_1$clock = clock;
        prev6$clock = clock;
        f7_1$clock = clock;
        prev7$clock = clock;
        f8_1$clock = clock;
        prev8$clock = clock;
        f8l$clock = clock;
        x_q$d = x_q$q;
        y_q$d = y_q$q;
        sr_q$d = sr_q$q;
        dxn_q$d = dxn_q$q;
        dxm_q$d = dxm_q$q;
        dyn_q$d = dyn_q$q;
        dym_q$d = dym_q$q;
        f0_1$d = f0_1$q;
        prev0$d = prev0$q;
        f1_1$d = f1_1$q;
        f1_2$d = f1_2$q;
        prev1$d = prev1$q;
        prev2$d = prev2$q;
        f3_1$d = f3_1$q;
        f3_2$d = f3_2$q;
        prev3$d = prev3$q;
        prev4$d = prev4$q;
        f5_1$d = f5_1$q;
        f5_2$d = f5_2$q;
        f5_3$d = f5_3$q;
        prev5$d = prev5$q;
        f6_1$d = f6_1$q;
        prev6$d = prev6$q;
        f7_1$d = f7_1$q;
        prev7$d = prev7$q;
        f8_1$d = f8_1$q;
        prev8$d = prev8$q;
        f8l$d = f8l$q;
        v_q$0$clock = clock;
        er_q$0$clock = clock;
        pad_q$0$clock = clock;
        bx_q$0$clock = clock;
        by_q$0$clock = clock;
        face_q$0$clock = clock;
        v_q$1$clock = clock;
        er_q$1$clock = clock;
        pad_q$1$clock = clock;
        bx_q$1$clock = clock;
        by_q$1$clock = clock;
        face_q$1$clock = clock;
        v_q$2$clock = clock;
        er_q$2$clock = clock;
        pad_q$2$clock = clock;
        bx_q$2$clock = clock;
        by_q$2$clock = clock;
        face_q$2$clock = clock;
        v_q$3$clock = clock;
        er_q$3$clock = clock;
        pad_q$3$clock = clock;
        bx_q$3$clock = clock;
        by_q$3$clock = clock;
        face_q$3$clock = clock;
        s_r$0$clock = clock;
        s_g$0$clock = clock;
        s_b$0$clock = clock;
        s_a$0$clock = clock;
        s_v$0$clock = clock;
        s_r$1$clock = clock;
        s_g$1$clock = clock;
        s_b$1$clock = clock;
        s_a$1$clock = clock;
        s_v$1$clock = clock;
        shader$clock = clock;
        bilinear$clock = clock;
        compositor$clock = clock;
        abc$clock = clock;
        abc$now = now;
        abc$valid = beat_valid & ~halo;
        abc$value = value;
        abc$x = x;
        abc$y = y;
        abc$pad = pad;
        abc$invalid = invalid;
        abc$sr = sr;
        abc$er = er;
        abc$at_edge = at_edge;
        abc$face = face;
        abc$base_x = base_x;
        abc$base_y = base_y;
        abc$dx_neg = dx_neg;
        abc$dx_mag = dx_mag;
        abc$dy_neg = dy_neg;
        abc$dy_mag = dy_mag;
        abc$from_left_xm = g_from_left_xm;
        abc$from_left_ym = g_from_left_ym;
        abc$from_left_zm = g_from_left_zm;
        abc$from_right_xp = g_from_right_xp;
        abc$from_right_yp = g_from_right_yp;
        abc$from_right_zp = g_from_right_zp;
        g_to_right_xm = abc$to_right_xm;
        g_to_right_ym = abc$to_right_ym;
        g_to_right_zm = abc$to_right_zm;
        g_to_left_xp = abc$to_left_xp;
        g_to_left_yp = abc$to_left_yp;
        g_to_left_zp = abc$to_left_zp;
        if (use_gradient) begin
            st_valid = abc$o_valid;
            st_value = abc$o_value;
            st_x = abc$o_x;
            st_y = abc$o_y;
            st_pad = abc$o_pad;
            st_invalid = abc$o_invalid;
            st_sr = abc$o_sr;
            st_er = abc$o_er;
            st_edge = abc$o_edge;
            st_face = abc$o_face;
            st_bx = abc$o_base_x;
            st_by = abc$o_base_y;
            st_dxn = abc$o_dx_neg;
            st_dxm = abc$o_dx_mag;
            st_dyn = abc$o_dy_neg;
            st_dym = abc$o_dy_mag;
        end
        else begin
            st_valid = beat_valid;
            st_value = value;
            st_x = x;
            st_y = y;
            st_pad = pad;
            st_invalid = invalid;
            st_sr = sr;
            st_er = er;
            st_edge = at_edge;
            st_face = face;
            st_bx = base_x;
            st_by = base_y;
            st_dxn = dx_neg;
            st_dxm = dx_mag;
            st_dyn = dy_neg;
            st_dym = dy_mag;
        end
        shader$value = st_value;
        shader$invalid = st_invalid;
        shader$at_edge = st_edge;
        shader$gx_neg = abc$gx_neg;
        shader$gx_mag = abc$gx_mag;
        shader$gy_neg = abc$gy_neg;
        shader$gy_mag = abc$gy_mag;
        shader$gz_neg = abc$gz_neg;
        shader$gz_mag = abc$gz_mag;
        v_q$0$d = st_valid;
        er_q$0$d = st_er;
        pad_q$0$d = st_pad;
        bx_q$0$d = st_bx;
        by_q$0$d = st_by;
        face_q$0$d = st_face;
        v_q$1$d = v_q$0$q;
        er_q$1$d = er_q$0$q;
        pad_q$1$d = pad_q$0$q;
        bx_q$1$d = bx_q$0$q;
        by_q$1$d = by_q$0$q;
        face_q$1$d = face_q$0$q;
        v_q$2$d = v_q$1$q;
        er_q$2$d = er_q$1$q;
        pad_q$2$d = pad_q$1$q;
        bx_q$2$d = bx_q$1$q;
        by_q$2$d = by_q$1$q;
        face_q$2$d = face_q$1$q;
        v_q$3$d = v_q$2$q;
        er_q$3$d = er_q$2$q;
        pad_q$3$d = pad_q$2$q;
        bx_q$3$d = bx_q$2$q;
        by_q$3$d = by_q$2$q;
        face_q$3$d = face_q$2$q;
        x_q$d = st_x;
        y_q$d = st_y;
        sr_q$d = st_sr;
        dxn_q$d = st_dxn;
        dxm_q$d = st_dxm;
        dyn_q$d = st_dyn;
        dym_q$d = st_dym;
        first = (x_q$q & p_mask) == 'h0;
        last = (x_q$q & p_mask) == p_mask;
        ring0$read_clock = clock;
        ring0$write_clock = clock;
        ring0$read_address = now + off0;
        t0s0 = ring0$read_data;
        f0_1$d = t0i1;
        s0 = ring0$read_data;
        if (hops0 == 'h1) begin
            s0 = f0_1$q;
        end
        prev0$d = s0;
        a0 = s0;
        ring1$read_clock = clock;
        ring1$write_clock = clock;
        ring1$read_address = now + off1;
        t1s0 = ring1$read_data;
        f1_1$d = t1i1;
        f1_2$d = t1i2;
        t1s1 = f1_1$q;
        s1 = ring1$read_data;
        if (hops1 == 'h1) begin
            s1 = f1_1$q;
        end
        if (hops1 == 'h2) begin
            s1 = f1_2$q;
        end
        prev1$d = s1;
        a1 = s1;
        if (first) begin
            a1 = prev1$q;
        end
        ring2$read_clock = clock;
        ring2$write_clock = clock;
        ring2$read_address = now + off2;
        s2 = ring2$read_data;
        prev2$d = s2;
        a2 = prev2$q;
        if (last) begin
            a2 = s2;
        end
        ring3$read_clock = clock;
        ring3$write_clock = clock;
        ring3$read_address = now + off3;
        t3s0 = ring3$read_data;
        f3_1$d = t3i1;
        f3_2$d = t3i2;
        t3s1 = f3_1$q;
        s3 = ring3$read_data;
        if (hops3 == 'h1) begin
            s3 = f3_1$q;
        end
        if (hops3 == 'h2) begin
            s3 = f3_2$q;
        end
        prev3$d = s3;
        a3 = s3;
        ring4$read_clock = clock;
        ring4$write_clock = clock;
        ring4$read_address = now + off4;
        s4 = ring4$read_data;
        prev4$d = s4;
        a4 = s4;
        ring5$read_clock = clock;
        ring5$write_clock = clock;
        ring5$read_address = now + off5;
        t5s0 = ring5$read_data;
        f5_1$d = t5i1;
        f5_2$d = t5i2;
        f5_3$d = t5i3;
        t5s1 = f5_1$q;
        t5s2 = f5_2$q;
        s5 = ring5$read_data;
        if (hops5 == 'h1) begin
            s5 = f5_1$q;
        end
        if (hops5 == 'h2) begin
            s5 = f5_2$q;
        end
        if (hops5 == 'h3) begin
            s5 = f5_3$q;
        end
        prev5$d = s5;
        a5 = s5;
        if (first) begin
            a5 = prev5$q;
        end
        ring6$read_clock = clock;
        ring6$write_clock = clock;
        ring6$read_address = now + off6;
        t6s0 = ring6$read_data;
        f6_1$d = t6i1;
        s6 = ring6$read_data;
        if (hops6 == 'h1) begin
            s6 = f6_1$q;
        end
        prev6$d = s6;
        a6 = prev6$q;
        if (last) begin
            a6 = s6;
        end
        ring7$read_clock = clock;
        ring7$write_clock = clock;
        ring7$read_address = now + off7;
        t7s0 = ring7$read_data;
        f7_1$d = t7i1;
        s7 = ring7$read_data;
        if (hops7 == 'h1) begin
            s7 = f7_1$q;
        end
        prev7$d = s7;
        a7 = s7;
        if (first) begin
            a7 = prev7$q;
        end
        ring8$read_clock = clock;
        ring8$write_clock = clock;
        ring8$read_address = now + off8;
        t8s0 = ring8$read_data;
        f8_1$d = t8i1;
        s8 = ring8$read_data;
        if (hops8 == 'h1) begin
            s8 = f8_1$q;
        end
        f8l$d = t8il;
        if (left8) begin
            s8 = f8l$q;
        end
        prev8$d = s8;
        a8 = prev8$q;
        if (last) begin
            a8 = s8;
        end
        c00 = a0;
        c10 = a0;
        c01 = a0;
        c11 = a0;
        x_out = 1'b0;
        y_out = 1'b0;
        if (dxm_q$q != 'h0) begin
            if (dxn_q$q) begin
                c10 = a2;
                x_out = x_q$q == nx_last;
            end
            else begin
                c10 = a1;
                x_out = x_q$q == 'h0;
            end
        end
        if (dym_q$q != 'h0) begin
            if (dyn_q$q) begin
                c01 = a4;
                y_out = y_q$q == ny_last;
            end
            else begin
                c01 = a3;
                y_out = y_q$q == 'h0;
            end
        end
        c11 = c01;
        if (dxm_q$q != 'h0) begin
            c11 = c10;
            if (dym_q$q != 'h0) begin
                if (dxn_q$q) begin
                    if (dyn_q$q) begin
                        c11 = a8;
                    end
                    else begin
                        c11 = a6;
                    end
                end
                else if (dyn_q$q) begin
                    c11 = a7;
                end
                else begin
                    c11 = a5;
                end
            end
        end
        if (x_out) begin
            c10 = reset;
            c11 = reset;
        end
        if (y_out) begin
            c01 = reset;
            c11 = reset;
        end
        if (sr_q$q) begin
            c00 = reset;
            c10 = reset;
            c01 = reset;
            c11 = reset;
        end
        bilinear$c00$0 = 32'(c00 & r_mask);
        bilinear$c00$1 = 32'((c00 >> 'h10) & gba_mask);
        bilinear$c00$2 = 32'((c00 >> 'h20) & gba_mask);
        bilinear$c00$3 = 32'((c00 >> 'h30) & gba_mask);
        bilinear$c10$0 = 32'(c10 & r_mask);
        bilinear$c10$1 = 32'((c10 >> 'h10) & gba_mask);
        bilinear$c10$2 = 32'((c10 >> 'h20) & gba_mask);
        bilinear$c10$3 = 32'((c10 >> 'h30) & gba_mask);
        bilinear$c01$0 = 32'(c01 & r_mask);
        bilinear$c01$1 = 32'((c01 >> 'h10) & gba_mask);
        bilinear$c01$2 = 32'((c01 >> 'h20) & gba_mask);
        bilinear$c01$3 = 32'((c01 >> 'h30) & gba_mask);
        bilinear$c11$0 = 32'(c11 & r_mask);
        bilinear$c11$1 = 32'((c11 >> 'h10) & gba_mask);
        bilinear$c11$2 = 32'((c11 >> 'h20) & gba_mask);
        bilinear$c11$3 = 32'((c11 >> 'h30) & gba_mask);
        bilinear$wx = dxm_q$q;
        bilinear$wy = dym_q$q;
        s_r$0$d = shader$r;
        s_g$0$d = shader$g;
        s_b$0$d = shader$b;
        s_a$0$d = shader$a;
        s_v$0$d = shader$valid;
        s_r$1$d = s_r$0$q;
        s_g$1$d = s_g$0$q;
        s_b$1$d = s_b$0$q;
        s_a$1$d = s_a$0$q;
        s_v$1$d = s_v$0$q;
        compositor$acc_r = bilinear$out$0;
        compositor$acc_g = 16'(bilinear$out$1);
        compositor$acc_b = 16'(bilinear$out$2);
        compositor$acc_a = 16'(bilinear$out$3);
        compositor$new_r = 32'(s_r$1$q);
        compositor$new_g = s_g$1$q;
        compositor$new_b = s_b$1$q;
        compositor$new_a = s_a$1$q;
        compositor$new_valid = s_v$1$q;
        res = 64'(compositor$out_r) | (64'(compositor$out_g) << 'h10) | (64'(compositor$out_b) << 'h20) | (64'(compositor$out_a) << 'h30);
        ring0$write_address = now - 'h3;
        ring0$write_data = res;
        ring0$write_enable = v_q$3$q;
        ring1$write_address = now - 'h3;
        ring1$write_data = res;
        ring1$write_enable = v_q$3$q;
        ring2$write_address = now - 'h3;
        ring2$write_data = res;
        ring2$write_enable = v_q$3$q;
        ring3$write_address = now - 'h3;
        ring3$write_data = res;
        ring3$write_enable = v_q$3$q;
        ring4$write_address = now - 'h3;
        ring4$write_data = res;
        ring4$write_enable = v_q$3$q;
        ring5$write_address = now - 'h3;
        ring5$write_data = res;
        ring5$write_enable = v_q$3$q;
        ring6$write_address = now - 'h3;
        ring6$write_data = res;
        ring6$write_enable = v_q$3$q;
        ring7$write_address = now - 'h3;
        ring7$write_data = res;
        ring7$write_enable = v_q$3$q;
        ring8$write_address = now - 'h3;
        ring8$write_data = res;
        ring8$write_enable = v_q$3$q;
        res_beat = v_q$3$q;
        res_valid = v_q$3$q & ~pad_q$3$q;
        px_valid = v_q$3$q & er_q$3$q & ~pad_q$3$q;
        px_x = bx_q$3$q;
        px_y = by_q$3$q;
        px_face = face_q$3$q;
    end
    
endmodule // top$lanes$0
module top$lanes$0$bx_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$0$bx_q$0
module top$lanes$0$bx_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$0$bx_q$1
module top$lanes$0$bx_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$0$bx_q$2
module top$lanes$0$bx_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$0$bx_q$3
module top$lanes$0$by_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$0$by_q$0
module top$lanes$0$by_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$0$by_q$1
module top$lanes$0$by_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$0$by_q$2
module top$lanes$0$by_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$0$by_q$3
module top$lanes$0$dxm_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$dxm_q
module top$lanes$0$dxn_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$dxn_q
module top$lanes$0$dym_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$dym_q
module top$lanes$0$dyn_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$dyn_q
module top$lanes$0$er_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$0$er_q$0
module top$lanes$0$er_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$0$er_q$1
module top$lanes$0$er_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$0$er_q$2
module top$lanes$0$er_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$0$er_q$3
module top$lanes$0$f0_1(d,q,clock);
    
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
          
endmodule // top$lanes$0$f0_1
module top$lanes$0$f1_1(d,q,clock);
    
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
          
endmodule // top$lanes$0$f1_1
module top$lanes$0$f1_2(d,q,clock);
    
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
          
endmodule // top$lanes$0$f1_2
module top$lanes$0$f3_1(d,q,clock);
    
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
          
endmodule // top$lanes$0$f3_1
module top$lanes$0$f3_2(d,q,clock);
    
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
          
endmodule // top$lanes$0$f3_2
module top$lanes$0$f5_1(d,q,clock);
    
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
          
endmodule // top$lanes$0$f5_1
module top$lanes$0$f5_2(d,q,clock);
    
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
          
endmodule // top$lanes$0$f5_2
module top$lanes$0$f5_3(d,q,clock);
    
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
          
endmodule // top$lanes$0$f5_3
module top$lanes$0$f6_1(d,q,clock);
    
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
          
endmodule // top$lanes$0$f6_1
module top$lanes$0$f7_1(d,q,clock);
    
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
          
endmodule // top$lanes$0$f7_1
module top$lanes$0$f8_1(d,q,clock);
    
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
          
endmodule // top$lanes$0$f8_1
module top$lanes$0$f8l(d,q,clock);
    
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
          
endmodule // top$lanes$0$f8l
module top$lanes$0$face_q$0(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$face_q$0
module top$lanes$0$face_q$1(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$face_q$1
module top$lanes$0$face_q$2(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$face_q$2
module top$lanes$0$face_q$3(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$face_q$3
module top$lanes$0$pad_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$0$pad_q$0
module top$lanes$0$pad_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$0$pad_q$1
module top$lanes$0$pad_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$0$pad_q$2
module top$lanes$0$pad_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$0$pad_q$3
module top$lanes$0$prev0(d,q,clock);
    
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
          
endmodule // top$lanes$0$prev0
module top$lanes$0$prev1(d,q,clock);
    
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
          
endmodule // top$lanes$0$prev1
module top$lanes$0$prev2(d,q,clock);
    
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
          
endmodule // top$lanes$0$prev2
module top$lanes$0$prev3(d,q,clock);
    
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
          
endmodule // top$lanes$0$prev3
module top$lanes$0$prev4(d,q,clock);
    
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
          
endmodule // top$lanes$0$prev4
module top$lanes$0$prev5(d,q,clock);
    
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
          
endmodule // top$lanes$0$prev5
module top$lanes$0$prev6(d,q,clock);
    
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
          
endmodule // top$lanes$0$prev6
module top$lanes$0$prev7(d,q,clock);
    
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
          
endmodule // top$lanes$0$prev7
module top$lanes$0$prev8(d,q,clock);
    
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
          
endmodule // top$lanes$0$prev8
module top$lanes$0$ring0(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[2047:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[10:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[10:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$0$ring0
module top$lanes$0$ring1(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[1:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[0:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[0:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$0$ring1
module top$lanes$0$ring2(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[2047:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[10:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[10:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$0$ring2
module top$lanes$0$ring3(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[2047:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[10:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[10:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$0$ring3
module top$lanes$0$ring4(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[1:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[0:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[0:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$0$ring4
module top$lanes$0$ring5(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[1:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[0:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[0:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$0$ring5
module top$lanes$0$ring6(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[2047:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[10:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[10:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$0$ring6
module top$lanes$0$ring7(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[1:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[0:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[0:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$0$ring7
module top$lanes$0$ring8(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[1:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[0:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[0:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$0$ring8
module top$lanes$0$s_a$0(d,q,clock);
    
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
          
endmodule // top$lanes$0$s_a$0
module top$lanes$0$s_a$1(d,q,clock);
    
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
          
endmodule // top$lanes$0$s_a$1
module top$lanes$0$s_b$0(d,q,clock);
    
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
          
endmodule // top$lanes$0$s_b$0
module top$lanes$0$s_b$1(d,q,clock);
    
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
          
endmodule // top$lanes$0$s_b$1
module top$lanes$0$s_g$0(d,q,clock);
    
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
          
endmodule // top$lanes$0$s_g$0
module top$lanes$0$s_g$1(d,q,clock);
    
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
          
endmodule // top$lanes$0$s_g$1
module top$lanes$0$s_r$0(d,q,clock);
    
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
          
endmodule // top$lanes$0$s_r$0
module top$lanes$0$s_r$1(d,q,clock);
    
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
          
endmodule // top$lanes$0$s_r$1
module top$lanes$0$s_v$0(d,q,clock);
    
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
          
endmodule // top$lanes$0$s_v$0
module top$lanes$0$s_v$1(d,q,clock);
    
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
          
endmodule // top$lanes$0$s_v$1
module top$lanes$0$sr_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$sr_q
module top$lanes$0$v_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$0$v_q$0
module top$lanes$0$v_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$0$v_q$1
module top$lanes$0$v_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$0$v_q$2
module top$lanes$0$v_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$0$v_q$3
module top$lanes$0$x_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$x_q
module top$lanes$0$y_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$y_q
module top$lanes$1(clock,now,beat_valid,value,x,y,pad,invalid,halo,sr,er,base_x,base_y,face,at_edge,dx_neg,dx_mag,dy_neg,dy_mag,g_from_left_xm,g_from_left_ym,g_from_left_zm,g_from_right_xp,g_from_right_yp,g_from_right_zp,g_to_right_xm,g_to_right_ym,g_to_right_zm,g_to_left_xp,g_to_left_yp,g_to_left_zp,t0s0,t0i1,t1s0,t1s1,t1i1,t1i2,t3s0,t3s1,t3i1,t3i2,t5s0,t5s1,t5s2,t5i1,t5i2,t5i3,t6s0,t6i1,t7s0,t7i1,t8s0,t8i1,t8il,res_beat,res_valid,res,px_valid,px_x,px_y,px_face);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] now;
    input wire  beat_valid;
    input wire  [15:0] value;
    input wire  [15:0] x;
    input wire  [15:0] y;
    input wire  pad;
    input wire  invalid;
    input wire  halo;
    input wire  sr;
    input wire  er;
    input wire  [15:0] base_x;
    input wire  [15:0] base_y;
    input wire  [2:0] face;
    input wire  at_edge;
    input wire  dx_neg;
    input wire  [15:0] dx_mag;
    input wire  dy_neg;
    input wire  [15:0] dy_mag;
    input wire  [15:0] g_from_left_xm;
    input wire  [15:0] g_from_left_ym;
    input wire  [15:0] g_from_left_zm;
    input wire  [15:0] g_from_right_xp;
    input wire  [15:0] g_from_right_yp;
    input wire  [15:0] g_from_right_zp;
    output reg  [15:0] g_to_right_xm;
    output reg  [15:0] g_to_right_ym;
    output reg  [15:0] g_to_right_zm;
    output reg  [15:0] g_to_left_xp;
    output reg  [15:0] g_to_left_yp;
    output reg  [15:0] g_to_left_zp;
    output reg  [63:0] t0s0;
    input wire  [63:0] t0i1;
    output reg  [63:0] t1s0;
    output reg  [63:0] t1s1;
    input wire  [63:0] t1i1;
    input wire  [63:0] t1i2;
    output reg  [63:0] t3s0;
    output reg  [63:0] t3s1;
    input wire  [63:0] t3i1;
    input wire  [63:0] t3i2;
    output reg  [63:0] t5s0;
    output reg  [63:0] t5s1;
    output reg  [63:0] t5s2;
    input wire  [63:0] t5i1;
    input wire  [63:0] t5i2;
    input wire  [63:0] t5i3;
    output reg  [63:0] t6s0;
    input wire  [63:0] t6i1;
    output reg  [63:0] t7s0;
    input wire  [63:0] t7i1;
    output reg  [63:0] t8s0;
    input wire  [63:0] t8i1;
    input wire  [63:0] t8il;
    output reg  res_beat;
    output reg  res_valid;
    output reg  [63:0] res;
    output reg  px_valid;
    output reg  [15:0] px_x;
    output reg  [15:0] px_y;
    output reg  [2:0] px_face;
    
    // Constant declarations
    localparam  use_gradient = 1'b0;
    localparam  hops0 = 2'b1;
    localparam  off0 = 16'hfc02;
    localparam  hops1 = 2'b10;
    localparam  off1 = 16'hfc03;
    localparam  off2 = 16'hfc02;
    localparam  hops3 = 2'b10;
    localparam  off3 = 16'hfbf3;
    localparam  off4 = 16'hfc11;
    localparam  hops5 = 2'b11;
    localparam  off5 = 16'hfbf4;
    localparam  hops6 = 2'b1;
    localparam  off6 = 16'hfbf3;
    localparam  hops7 = 2'b1;
    localparam  off7 = 16'hfc12;
    localparam  hops8 = 2'b1;
    localparam  off8 = 16'hfc13;
    localparam  left8 = 1'b1;
    localparam  p_mask = 16'h3;
    localparam  nx_last = 16'h3f;
    localparam  ny_last = 16'h3f;
    localparam  reset = 64'h0;
    localparam  r_mask = 64'hffff;
    localparam  gba_mask = 64'hffff;
    
    // Stub signals
    reg  abc$clock;
    reg  [15:0] abc$now;
    reg  abc$valid;
    reg  [15:0] abc$value;
    reg  [15:0] abc$x;
    reg  [15:0] abc$y;
    reg  abc$pad;
    reg  abc$invalid;
    reg  abc$dx_neg;
    reg  [15:0] abc$dx_mag;
    reg  abc$dy_neg;
    reg  [15:0] abc$dy_mag;
    reg  abc$sr;
    reg  abc$er;
    reg  abc$at_edge;
    reg  [2:0] abc$face;
    reg  [15:0] abc$base_x;
    reg  [15:0] abc$base_y;
    reg  [15:0] abc$from_left_xm;
    reg  [15:0] abc$from_left_ym;
    reg  [15:0] abc$from_left_zm;
    reg  [15:0] abc$from_right_xp;
    reg  [15:0] abc$from_right_yp;
    reg  [15:0] abc$from_right_zp;
    wire  [15:0] abc$to_right_xm = 'h0;
    wire  [15:0] abc$to_right_ym = 'h0;
    wire  [15:0] abc$to_right_zm = 'h0;
    wire  [15:0] abc$to_left_xp = 'h0;
    wire  [15:0] abc$to_left_yp = 'h0;
    wire  [15:0] abc$to_left_zp = 'h0;
    wire  abc$o_valid = 'h0;
    wire  [15:0] abc$o_value = 'h0;
    wire  [15:0] abc$o_x = 'h0;
    wire  [15:0] abc$o_y = 'h0;
    wire  abc$o_pad = 'h0;
    wire  abc$o_invalid = 'h0;
    wire  abc$o_dx_neg = 'h0;
    wire  [15:0] abc$o_dx_mag = 'h0;
    wire  abc$o_dy_neg = 'h0;
    wire  [15:0] abc$o_dy_mag = 'h0;
    wire  abc$o_sr = 'h0;
    wire  abc$o_er = 'h0;
    wire  abc$o_edge = 'h0;
    wire  [2:0] abc$o_face = 'h0;
    wire  [15:0] abc$o_base_x = 'h0;
    wire  [15:0] abc$o_base_y = 'h0;
    wire  abc$gx_neg = 'h0;
    wire  [15:0] abc$gx_mag = 'h0;
    wire  abc$gy_neg = 'h0;
    wire  [15:0] abc$gy_mag = 'h0;
    wire  abc$gz_neg = 'h0;
    wire  [15:0] abc$gz_mag = 'h0;
    reg  shader$clock;
    reg  [15:0] shader$value;
    reg  shader$invalid;
    reg  shader$at_edge;
    reg  shader$gx_neg;
    reg  [15:0] shader$gx_mag;
    reg  shader$gy_neg;
    reg  [15:0] shader$gy_mag;
    reg  shader$gz_neg;
    reg  [15:0] shader$gz_mag;
    wire  [15:0] shader$r;
    wire  [15:0] shader$g;
    wire  [15:0] shader$b;
    wire  [15:0] shader$a;
    wire  shader$valid;
    reg  [15:0] ring0$read_address;
    reg  ring0$read_clock;
    wire  [63:0] ring0$read_data;
    reg  [15:0] ring0$write_address;
    reg  ring0$write_clock;
    reg  [63:0] ring0$write_data;
    reg  ring0$write_enable;
    reg  [63:0] f0_1$d;
    wire  [63:0] f0_1$q;
    reg  f0_1$clock;
    reg  [63:0] prev0$d;
    wire  [63:0] prev0$q;
    reg  prev0$clock;
    reg  [15:0] ring1$read_address;
    reg  ring1$read_clock;
    wire  [63:0] ring1$read_data;
    reg  [15:0] ring1$write_address;
    reg  ring1$write_clock;
    reg  [63:0] ring1$write_data;
    reg  ring1$write_enable;
    reg  [63:0] f1_1$d;
    wire  [63:0] f1_1$q;
    reg  f1_1$clock;
    reg  [63:0] f1_2$d;
    wire  [63:0] f1_2$q;
    reg  f1_2$clock;
    reg  [63:0] prev1$d;
    wire  [63:0] prev1$q;
    reg  prev1$clock;
    reg  [15:0] ring2$read_address;
    reg  ring2$read_clock;
    wire  [63:0] ring2$read_data;
    reg  [15:0] ring2$write_address;
    reg  ring2$write_clock;
    reg  [63:0] ring2$write_data;
    reg  ring2$write_enable;
    reg  [63:0] prev2$d;
    wire  [63:0] prev2$q;
    reg  prev2$clock;
    reg  [15:0] ring3$read_address;
    reg  ring3$read_clock;
    wire  [63:0] ring3$read_data;
    reg  [15:0] ring3$write_address;
    reg  ring3$write_clock;
    reg  [63:0] ring3$write_data;
    reg  ring3$write_enable;
    reg  [63:0] f3_1$d;
    wire  [63:0] f3_1$q;
    reg  f3_1$clock;
    reg  [63:0] f3_2$d;
    wire  [63:0] f3_2$q;
    reg  f3_2$clock;
    reg  [63:0] prev3$d;
    wire  [63:0] prev3$q;
    reg  prev3$clock;
    reg  [15:0] ring4$read_address;
    reg  ring4$read_clock;
    wire  [63:0] ring4$read_data;
    reg  [15:0] ring4$write_address;
    reg  ring4$write_clock;
    reg  [63:0] ring4$write_data;
    reg  ring4$write_enable;
    reg  [63:0] prev4$d;
    wire  [63:0] prev4$q;
    reg  prev4$clock;
    reg  [15:0] ring5$read_address;
    reg  ring5$read_clock;
    wire  [63:0] ring5$read_data;
    reg  [15:0] ring5$write_address;
    reg  ring5$write_clock;
    reg  [63:0] ring5$write_data;
    reg  ring5$write_enable;
    reg  [63:0] f5_1$d;
    wire  [63:0] f5_1$q;
    reg  f5_1$clock;
    reg  [63:0] f5_2$d;
    wire  [63:0] f5_2$q;
    reg  f5_2$clock;
    reg  [63:0] f5_3$d;
    wire  [63:0] f5_3$q;
    reg  f5_3$clock;
    reg  [63:0] prev5$d;
    wire  [63:0] prev5$q;
    reg  prev5$clock;
    reg  [15:0] ring6$read_address;
    reg  ring6$read_clock;
    wire  [63:0] ring6$read_data;
    reg  [15:0] ring6$write_address;
    reg  ring6$write_clock;
    reg  [63:0] ring6$write_data;
    reg  ring6$write_enable;
    reg  [63:0] f6_1$d;
    wire  [63:0] f6_1$q;
    reg  f6_1$clock;
    reg  [63:0] prev6$d;
    wire  [63:0] prev6$q;
    reg  prev6$clock;
    reg  [15:0] ring7$read_address;
    reg  ring7$read_clock;
    wire  [63:0] ring7$read_data;
    reg  [15:0] ring7$write_address;
    reg  ring7$write_clock;
    reg  [63:0] ring7$write_data;
    reg  ring7$write_enable;
    reg  [63:0] f7_1$d;
    wire  [63:0] f7_1$q;
    reg  f7_1$clock;
    reg  [63:0] prev7$d;
    wire  [63:0] prev7$q;
    reg  prev7$clock;
    reg  [15:0] ring8$read_address;
    reg  ring8$read_clock;
    wire  [63:0] ring8$read_data;
    reg  [15:0] ring8$write_address;
    reg  ring8$write_clock;
    reg  [63:0] ring8$write_data;
    reg  ring8$write_enable;
    reg  [63:0] f8_1$d;
    wire  [63:0] f8_1$q;
    reg  f8_1$clock;
    reg  [63:0] prev8$d;
    wire  [63:0] prev8$q;
    reg  prev8$clock;
    reg  [63:0] f8l$d;
    wire  [63:0] f8l$q;
    reg  f8l$clock;
    reg  bilinear$clock;
    reg  [31:0] bilinear$c00$0;
    reg  [31:0] bilinear$c00$1;
    reg  [31:0] bilinear$c00$2;
    reg  [31:0] bilinear$c00$3;
    reg  [31:0] bilinear$c10$0;
    reg  [31:0] bilinear$c10$1;
    reg  [31:0] bilinear$c10$2;
    reg  [31:0] bilinear$c10$3;
    reg  [31:0] bilinear$c01$0;
    reg  [31:0] bilinear$c01$1;
    reg  [31:0] bilinear$c01$2;
    reg  [31:0] bilinear$c01$3;
    reg  [31:0] bilinear$c11$0;
    reg  [31:0] bilinear$c11$1;
    reg  [31:0] bilinear$c11$2;
    reg  [31:0] bilinear$c11$3;
    reg  [15:0] bilinear$wx;
    reg  [15:0] bilinear$wy;
    wire  [31:0] bilinear$out$0;
    wire  [31:0] bilinear$out$1;
    wire  [31:0] bilinear$out$2;
    wire  [31:0] bilinear$out$3;
    reg  compositor$clock;
    reg  [31:0] compositor$acc_r;
    reg  [15:0] compositor$acc_g;
    reg  [15:0] compositor$acc_b;
    reg  [15:0] compositor$acc_a;
    reg  [31:0] compositor$new_r;
    reg  [15:0] compositor$new_g;
    reg  [15:0] compositor$new_b;
    reg  [15:0] compositor$new_a;
    reg  compositor$new_valid;
    wire  [31:0] compositor$out_r;
    wire  [15:0] compositor$out_g;
    wire  [15:0] compositor$out_b;
    wire  [15:0] compositor$out_a;
    reg  v_q$0$d;
    wire  v_q$0$q;
    reg  v_q$0$clock;
    reg  v_q$1$d;
    wire  v_q$1$q;
    reg  v_q$1$clock;
    reg  v_q$2$d;
    wire  v_q$2$q;
    reg  v_q$2$clock;
    reg  v_q$3$d;
    wire  v_q$3$q;
    reg  v_q$3$clock;
    reg  er_q$0$d;
    wire  er_q$0$q;
    reg  er_q$0$clock;
    reg  er_q$1$d;
    wire  er_q$1$q;
    reg  er_q$1$clock;
    reg  er_q$2$d;
    wire  er_q$2$q;
    reg  er_q$2$clock;
    reg  er_q$3$d;
    wire  er_q$3$q;
    reg  er_q$3$clock;
    reg  pad_q$0$d;
    wire  pad_q$0$q;
    reg  pad_q$0$clock;
    reg  pad_q$1$d;
    wire  pad_q$1$q;
    reg  pad_q$1$clock;
    reg  pad_q$2$d;
    wire  pad_q$2$q;
    reg  pad_q$2$clock;
    reg  pad_q$3$d;
    wire  pad_q$3$q;
    reg  pad_q$3$clock;
    reg  [15:0] bx_q$0$d;
    wire  [15:0] bx_q$0$q;
    reg  bx_q$0$clock;
    reg  [15:0] bx_q$1$d;
    wire  [15:0] bx_q$1$q;
    reg  bx_q$1$clock;
    reg  [15:0] bx_q$2$d;
    wire  [15:0] bx_q$2$q;
    reg  bx_q$2$clock;
    reg  [15:0] bx_q$3$d;
    wire  [15:0] bx_q$3$q;
    reg  bx_q$3$clock;
    reg  [15:0] by_q$0$d;
    wire  [15:0] by_q$0$q;
    reg  by_q$0$clock;
    reg  [15:0] by_q$1$d;
    wire  [15:0] by_q$1$q;
    reg  by_q$1$clock;
    reg  [15:0] by_q$2$d;
    wire  [15:0] by_q$2$q;
    reg  by_q$2$clock;
    reg  [15:0] by_q$3$d;
    wire  [15:0] by_q$3$q;
    reg  by_q$3$clock;
    reg  [2:0] face_q$0$d;
    wire  [2:0] face_q$0$q;
    reg  face_q$0$clock;
    reg  [2:0] face_q$1$d;
    wire  [2:0] face_q$1$q;
    reg  face_q$1$clock;
    reg  [2:0] face_q$2$d;
    wire  [2:0] face_q$2$q;
    reg  face_q$2$clock;
    reg  [2:0] face_q$3$d;
    wire  [2:0] face_q$3$q;
    reg  face_q$3$clock;
    reg  [15:0] x_q$d;
    wire  [15:0] x_q$q;
    reg  x_q$clock;
    reg  [15:0] y_q$d;
    wire  [15:0] y_q$q;
    reg  y_q$clock;
    reg  sr_q$d;
    wire  sr_q$q;
    reg  sr_q$clock;
    reg  dxn_q$d;
    wire  dxn_q$q;
    reg  dxn_q$clock;
    reg  [15:0] dxm_q$d;
    wire  [15:0] dxm_q$q;
    reg  dxm_q$clock;
    reg  dyn_q$d;
    wire  dyn_q$q;
    reg  dyn_q$clock;
    reg  [15:0] dym_q$d;
    wire  [15:0] dym_q$q;
    reg  dym_q$clock;
    reg  [15:0] s_r$0$d;
    wire  [15:0] s_r$0$q;
    reg  s_r$0$clock;
    reg  [15:0] s_r$1$d;
    wire  [15:0] s_r$1$q;
    reg  s_r$1$clock;
    reg  [15:0] s_g$0$d;
    wire  [15:0] s_g$0$q;
    reg  s_g$0$clock;
    reg  [15:0] s_g$1$d;
    wire  [15:0] s_g$1$q;
    reg  s_g$1$clock;
    reg  [15:0] s_b$0$d;
    wire  [15:0] s_b$0$q;
    reg  s_b$0$clock;
    reg  [15:0] s_b$1$d;
    wire  [15:0] s_b$1$q;
    reg  s_b$1$clock;
    reg  [15:0] s_a$0$d;
    wire  [15:0] s_a$0$q;
    reg  s_a$0$clock;
    reg  [15:0] s_a$1$d;
    wire  [15:0] s_a$1$q;
    reg  s_a$1$clock;
    reg  s_v$0$d;
    wire  s_v$0$q;
    reg  s_v$0$clock;
    reg  s_v$1$d;
    wire  s_v$1$q;
    reg  s_v$1$clock;
    
    // Local signals
    reg  st_valid;
    reg  [15:0] st_value;
    reg  [15:0] st_x;
    reg  [15:0] st_y;
    reg  st_pad;
    reg  st_invalid;
    reg  st_sr;
    reg  st_er;
    reg  st_edge;
    reg  [2:0] st_face;
    reg  [15:0] st_bx;
    reg  [15:0] st_by;
    reg  st_dxn;
    reg  [15:0] st_dxm;
    reg  st_dyn;
    reg  [15:0] st_dym;
    reg  [63:0] s0;
    reg  [63:0] a0;
    reg  [63:0] s1;
    reg  [63:0] a1;
    reg  [63:0] s2;
    reg  [63:0] a2;
    reg  [63:0] s3;
    reg  [63:0] a3;
    reg  [63:0] s4;
    reg  [63:0] a4;
    reg  [63:0] s5;
    reg  [63:0] a5;
    reg  [63:0] s6;
    reg  [63:0] a6;
    reg  [63:0] s7;
    reg  [63:0] a7;
    reg  [63:0] s8;
    reg  [63:0] a8;
    reg  first;
    reg  last;
    reg  [63:0] c00;
    reg  [63:0] c10;
    reg  [63:0] c01;
    reg  [63:0] c11;
    reg  x_out;
    reg  y_out;
    
    // Sub module instances
    top$lanes$1$shader shader(
        .clock(shader$clock),
        .value(shader$value),
        .invalid(shader$invalid),
        .at_edge(shader$at_edge),
        .gx_neg(shader$gx_neg),
        .gx_mag(shader$gx_mag),
        .gy_neg(shader$gy_neg),
        .gy_mag(shader$gy_mag),
        .gz_neg(shader$gz_neg),
        .gz_mag(shader$gz_mag),
        .r(shader$r),
        .g(shader$g),
        .b(shader$b),
        .a(shader$a),
        .valid(shader$valid)
    );
    top$lanes$1$ring0 ring0(
        .read_address(ring0$read_address),
        .read_clock(ring0$read_clock),
        .read_data(ring0$read_data),
        .write_address(ring0$write_address),
        .write_clock(ring0$write_clock),
        .write_data(ring0$write_data),
        .write_enable(ring0$write_enable)
    );
    top$lanes$1$f0_1 f0_1(
        .d(f0_1$d),
        .q(f0_1$q),
        .clock(f0_1$clock)
    );
    top$lanes$1$prev0 prev0(
        .d(prev0$d),
        .q(prev0$q),
        .clock(prev0$clock)
    );
    top$lanes$1$ring1 ring1(
        .read_address(ring1$read_address),
        .read_clock(ring1$read_clock),
        .read_data(ring1$read_data),
        .write_address(ring1$write_address),
        .write_clock(ring1$write_clock),
        .write_data(ring1$write_data),
        .write_enable(ring1$write_enable)
    );
    top$lanes$1$f1_1 f1_1(
        .d(f1_1$d),
        .q(f1_1$q),
        .clock(f1_1$clock)
    );
    top$lanes$1$f1_2 f1_2(
        .d(f1_2$d),
        .q(f1_2$q),
        .clock(f1_2$clock)
    );
    top$lanes$1$prev1 prev1(
        .d(prev1$d),
        .q(prev1$q),
        .clock(prev1$clock)
    );
    top$lanes$1$ring2 ring2(
        .read_address(ring2$read_address),
        .read_clock(ring2$read_clock),
        .read_data(ring2$read_data),
        .write_address(ring2$write_address),
        .write_clock(ring2$write_clock),
        .write_data(ring2$write_data),
        .write_enable(ring2$write_enable)
    );
    top$lanes$1$prev2 prev2(
        .d(prev2$d),
        .q(prev2$q),
        .clock(prev2$clock)
    );
    top$lanes$1$ring3 ring3(
        .read_address(ring3$read_address),
        .read_clock(ring3$read_clock),
        .read_data(ring3$read_data),
        .write_address(ring3$write_address),
        .write_clock(ring3$write_clock),
        .write_data(ring3$write_data),
        .write_enable(ring3$write_enable)
    );
    top$lanes$1$f3_1 f3_1(
        .d(f3_1$d),
        .q(f3_1$q),
        .clock(f3_1$clock)
    );
    top$lanes$1$f3_2 f3_2(
        .d(f3_2$d),
        .q(f3_2$q),
        .clock(f3_2$clock)
    );
    top$lanes$1$prev3 prev3(
        .d(prev3$d),
        .q(prev3$q),
        .clock(prev3$clock)
    );
    top$lanes$1$ring4 ring4(
        .read_address(ring4$read_address),
        .read_clock(ring4$read_clock),
        .read_data(ring4$read_data),
        .write_address(ring4$write_address),
        .write_clock(ring4$write_clock),
        .write_data(ring4$write_data),
        .write_enable(ring4$write_enable)
    );
    top$lanes$1$prev4 prev4(
        .d(prev4$d),
        .q(prev4$q),
        .clock(prev4$clock)
    );
    top$lanes$1$ring5 ring5(
        .read_address(ring5$read_address),
        .read_clock(ring5$read_clock),
        .read_data(ring5$read_data),
        .write_address(ring5$write_address),
        .write_clock(ring5$write_clock),
        .write_data(ring5$write_data),
        .write_enable(ring5$write_enable)
    );
    top$lanes$1$f5_1 f5_1(
        .d(f5_1$d),
        .q(f5_1$q),
        .clock(f5_1$clock)
    );
    top$lanes$1$f5_2 f5_2(
        .d(f5_2$d),
        .q(f5_2$q),
        .clock(f5_2$clock)
    );
    top$lanes$1$f5_3 f5_3(
        .d(f5_3$d),
        .q(f5_3$q),
        .clock(f5_3$clock)
    );
    top$lanes$1$prev5 prev5(
        .d(prev5$d),
        .q(prev5$q),
        .clock(prev5$clock)
    );
    top$lanes$1$ring6 ring6(
        .read_address(ring6$read_address),
        .read_clock(ring6$read_clock),
        .read_data(ring6$read_data),
        .write_address(ring6$write_address),
        .write_clock(ring6$write_clock),
        .write_data(ring6$write_data),
        .write_enable(ring6$write_enable)
    );
    top$lanes$1$f6_1 f6_1(
        .d(f6_1$d),
        .q(f6_1$q),
        .clock(f6_1$clock)
    );
    top$lanes$1$prev6 prev6(
        .d(prev6$d),
        .q(prev6$q),
        .clock(prev6$clock)
    );
    top$lanes$1$ring7 ring7(
        .read_address(ring7$read_address),
        .read_clock(ring7$read_clock),
        .read_data(ring7$read_data),
        .write_address(ring7$write_address),
        .write_clock(ring7$write_clock),
        .write_data(ring7$write_data),
        .write_enable(ring7$write_enable)
    );
    top$lanes$1$f7_1 f7_1(
        .d(f7_1$d),
        .q(f7_1$q),
        .clock(f7_1$clock)
    );
    top$lanes$1$prev7 prev7(
        .d(prev7$d),
        .q(prev7$q),
        .clock(prev7$clock)
    );
    top$lanes$1$ring8 ring8(
        .read_address(ring8$read_address),
        .read_clock(ring8$read_clock),
        .read_data(ring8$read_data),
        .write_address(ring8$write_address),
        .write_clock(ring8$write_clock),
        .write_data(ring8$write_data),
        .write_enable(ring8$write_enable)
    );
    top$lanes$1$f8_1 f8_1(
        .d(f8_1$d),
        .q(f8_1$q),
        .clock(f8_1$clock)
    );
    top$lanes$1$prev8 prev8(
        .d(prev8$d),
        .q(prev8$q),
        .clock(prev8$clock)
    );
    top$lanes$1$f8l f8l(
        .d(f8l$d),
        .q(f8l$q),
        .clock(f8l$clock)
    );
    top$lanes$1$bilinear bilinear(
        .clock(bilinear$clock),
        .c00$0(bilinear$c00$0),
        .c00$1(bilinear$c00$1),
        .c00$2(bilinear$c00$2),
        .c00$3(bilinear$c00$3),
        .c10$0(bilinear$c10$0),
        .c10$1(bilinear$c10$1),
        .c10$2(bilinear$c10$2),
        .c10$3(bilinear$c10$3),
        .c01$0(bilinear$c01$0),
        .c01$1(bilinear$c01$1),
        .c01$2(bilinear$c01$2),
        .c01$3(bilinear$c01$3),
        .c11$0(bilinear$c11$0),
        .c11$1(bilinear$c11$1),
        .c11$2(bilinear$c11$2),
        .c11$3(bilinear$c11$3),
        .wx(bilinear$wx),
        .wy(bilinear$wy),
        .out$0(bilinear$out$0),
        .out$1(bilinear$out$1),
        .out$2(bilinear$out$2),
        .out$3(bilinear$out$3)
    );
    top$lanes$1$compositor compositor(
        .clock(compositor$clock),
        .acc_r(compositor$acc_r),
        .acc_g(compositor$acc_g),
        .acc_b(compositor$acc_b),
        .acc_a(compositor$acc_a),
        .new_r(compositor$new_r),
        .new_g(compositor$new_g),
        .new_b(compositor$new_b),
        .new_a(compositor$new_a),
        .new_valid(compositor$new_valid),
        .out_r(compositor$out_r),
        .out_g(compositor$out_g),
        .out_b(compositor$out_b),
        .out_a(compositor$out_a)
    );
    top$lanes$1$v_q$0 v_q$0(
        .d(v_q$0$d),
        .q(v_q$0$q),
        .clock(v_q$0$clock)
    );
    top$lanes$1$v_q$1 v_q$1(
        .d(v_q$1$d),
        .q(v_q$1$q),
        .clock(v_q$1$clock)
    );
    top$lanes$1$v_q$2 v_q$2(
        .d(v_q$2$d),
        .q(v_q$2$q),
        .clock(v_q$2$clock)
    );
    top$lanes$1$v_q$3 v_q$3(
        .d(v_q$3$d),
        .q(v_q$3$q),
        .clock(v_q$3$clock)
    );
    top$lanes$1$er_q$0 er_q$0(
        .d(er_q$0$d),
        .q(er_q$0$q),
        .clock(er_q$0$clock)
    );
    top$lanes$1$er_q$1 er_q$1(
        .d(er_q$1$d),
        .q(er_q$1$q),
        .clock(er_q$1$clock)
    );
    top$lanes$1$er_q$2 er_q$2(
        .d(er_q$2$d),
        .q(er_q$2$q),
        .clock(er_q$2$clock)
    );
    top$lanes$1$er_q$3 er_q$3(
        .d(er_q$3$d),
        .q(er_q$3$q),
        .clock(er_q$3$clock)
    );
    top$lanes$1$pad_q$0 pad_q$0(
        .d(pad_q$0$d),
        .q(pad_q$0$q),
        .clock(pad_q$0$clock)
    );
    top$lanes$1$pad_q$1 pad_q$1(
        .d(pad_q$1$d),
        .q(pad_q$1$q),
        .clock(pad_q$1$clock)
    );
    top$lanes$1$pad_q$2 pad_q$2(
        .d(pad_q$2$d),
        .q(pad_q$2$q),
        .clock(pad_q$2$clock)
    );
    top$lanes$1$pad_q$3 pad_q$3(
        .d(pad_q$3$d),
        .q(pad_q$3$q),
        .clock(pad_q$3$clock)
    );
    top$lanes$1$bx_q$0 bx_q$0(
        .d(bx_q$0$d),
        .q(bx_q$0$q),
        .clock(bx_q$0$clock)
    );
    top$lanes$1$bx_q$1 bx_q$1(
        .d(bx_q$1$d),
        .q(bx_q$1$q),
        .clock(bx_q$1$clock)
    );
    top$lanes$1$bx_q$2 bx_q$2(
        .d(bx_q$2$d),
        .q(bx_q$2$q),
        .clock(bx_q$2$clock)
    );
    top$lanes$1$bx_q$3 bx_q$3(
        .d(bx_q$3$d),
        .q(bx_q$3$q),
        .clock(bx_q$3$clock)
    );
    top$lanes$1$by_q$0 by_q$0(
        .d(by_q$0$d),
        .q(by_q$0$q),
        .clock(by_q$0$clock)
    );
    top$lanes$1$by_q$1 by_q$1(
        .d(by_q$1$d),
        .q(by_q$1$q),
        .clock(by_q$1$clock)
    );
    top$lanes$1$by_q$2 by_q$2(
        .d(by_q$2$d),
        .q(by_q$2$q),
        .clock(by_q$2$clock)
    );
    top$lanes$1$by_q$3 by_q$3(
        .d(by_q$3$d),
        .q(by_q$3$q),
        .clock(by_q$3$clock)
    );
    top$lanes$1$face_q$0 face_q$0(
        .d(face_q$0$d),
        .q(face_q$0$q),
        .clock(face_q$0$clock)
    );
    top$lanes$1$face_q$1 face_q$1(
        .d(face_q$1$d),
        .q(face_q$1$q),
        .clock(face_q$1$clock)
    );
    top$lanes$1$face_q$2 face_q$2(
        .d(face_q$2$d),
        .q(face_q$2$q),
        .clock(face_q$2$clock)
    );
    top$lanes$1$face_q$3 face_q$3(
        .d(face_q$3$d),
        .q(face_q$3$q),
        .clock(face_q$3$clock)
    );
    top$lanes$1$x_q x_q(
        .d(x_q$d),
        .q(x_q$q),
        .clock(x_q$clock)
    );
    top$lanes$1$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    top$lanes$1$sr_q sr_q(
        .d(sr_q$d),
        .q(sr_q$q),
        .clock(sr_q$clock)
    );
    top$lanes$1$dxn_q dxn_q(
        .d(dxn_q$d),
        .q(dxn_q$q),
        .clock(dxn_q$clock)
    );
    top$lanes$1$dxm_q dxm_q(
        .d(dxm_q$d),
        .q(dxm_q$q),
        .clock(dxm_q$clock)
    );
    top$lanes$1$dyn_q dyn_q(
        .d(dyn_q$d),
        .q(dyn_q$q),
        .clock(dyn_q$clock)
    );
    top$lanes$1$dym_q dym_q(
        .d(dym_q$d),
        .q(dym_q$q),
        .clock(dym_q$clock)
    );
    top$lanes$1$s_r$0 s_r$0(
        .d(s_r$0$d),
        .q(s_r$0$q),
        .clock(s_r$0$clock)
    );
    top$lanes$1$s_r$1 s_r$1(
        .d(s_r$1$d),
        .q(s_r$1$q),
        .clock(s_r$1$clock)
    );
    top$lanes$1$s_g$0 s_g$0(
        .d(s_g$0$d),
        .q(s_g$0$q),
        .clock(s_g$0$clock)
    );
    top$lanes$1$s_g$1 s_g$1(
        .d(s_g$1$d),
        .q(s_g$1$q),
        .clock(s_g$1$clock)
    );
    top$lanes$1$s_b$0 s_b$0(
        .d(s_b$0$d),
        .q(s_b$0$q),
        .clock(s_b$0$clock)
    );
    top$lanes$1$s_b$1 s_b$1(
        .d(s_b$1$d),
        .q(s_b$1$q),
        .clock(s_b$1$clock)
    );
    top$lanes$1$s_a$0 s_a$0(
        .d(s_a$0$d),
        .q(s_a$0$q),
        .clock(s_a$0$clock)
    );
    top$lanes$1$s_a$1 s_a$1(
        .d(s_a$1$d),
        .q(s_a$1$q),
        .clock(s_a$1$clock)
    );
    top$lanes$1$s_v$0 s_v$0(
        .d(s_v$0$d),
        .q(s_v$0$q),
        .clock(s_v$0$clock)
    );
    top$lanes$1$s_v$1 s_v$1(
        .d(s_v$1$d),
        .q(s_v$1$q),
        .clock(s_v$1$clock)
    );
    
    // Update code
    always @(*) begin
        x_q$clock = clock;
        y_q$clock = clock;
        sr_q$clock = clock;
        dxn_q$clock = clock;
        dxm_q$clock = clock;
        dyn_q$clock = clock;
        dym_q$clock = clock;
        f0_1$clock = clock;
        prev0$clock = clock;
        f1_1$clock = clock;
        f1_2$clock = clock;
        prev1$clock = clock;
        prev2$clock = clock;
        f3_1$clock = clock;
        f3_2$clock = clock;
        prev3$clock = clock;
        prev4$clock = clock;
        f5_1$clock = clock;
        f5_2$clock = clock;
        f5_3$clock = clock;
        prev5$clock = clock;
        f6_1$clock = clock;
        prev6$clock = clock;
        f7_1$clock = clock;
        prev7$clock = clock;
        f8_1$clock = clock;
        prev8$clock = clock;
        f8l$clock = clock;
        x_q$d = x_q$q;
        y_q$d = y_q$q;
        sr_q$d = sr_q$q;
        dxn_q$d = dxn_q$q;
        dxm_q$d = dxm_q$q;
        dyn_q$d = dyn_q$q;
        dym_q$d = dym_q$q;
        f0_1$d = f0_1$q;
        prev0$d = prev0$q;
        f1_1$d = f1_1$q;
        f1_2$d = f1_2$q;
        prev1$d = prev1$q;
        prev2$d = prev2$q;
        f3_1$d = f3_1$q;
        f3_2$d = f3_2$q;
        prev3$d = prev3$q;
        prev4$d = prev4$q;
        f5_1$d = f5_1$q;
        f5_2$d = f5_2$q;
        f5_3$d = f5_3$q;
        prev5$d = prev5$q;
        f6_1$d = f6_1$q;
        prev6$d = prev6$q;
        f7_1$d = f7_1$q;
        prev7$d = prev7$q;
        f8_1$d = f8_1$q;
        prev8$d = prev8$q;
        f8l$d = f8l$q;
        v_q$0$clock = clock;
        er_q$0$clock = clock;
        pad_q$0$clock = clock;
        bx_q$0$clock = clock;
        by_q$0$clock = clock;
        face_q$0$clock = clock;
        v_q$1$clock = clock;
        er_q$1$clock = clock;
        pad_q$1$clock = clock;
        bx_q$1$clock = clock;
        by_q$1$clock = clock;
        face_q$1$clock = clock;
        v_q$2$clock = clock;
        er_q$2$clock = clock;
        pad_q$2$clock = clock;
        bx_q$2$clock = clock;
        by_q$2$clock = clock;
        face_q$2$clock = clock;
        v_q$3$clock = clock;
        er_q$3$clock = clock;
        pad_q$3$clock = clock;
        bx_q$3$clock = clock;
        by_q$3$clock = clock;
        face_q$3$clock = clock;
        s_r$0$clock = clock;
        s_g$0$clock = clock;
        s_b$0$clock = clock;
        s_a$0$clock = clock;
        s_v$0$clock = clock;
        s_r$1$clock = clock;
        s_g$1$clock = clock;
        s_b$1$clock = clock;
        s_a$1$clock = clock;
        s_v$1$clock = clock;
        shader$clock = clock;
        bilinear$clock = clock;
        compositor$clock = clock;
        abc$clock = clock;
        abc$now = now;
        abc$valid = beat_valid & ~halo;
        abc$value = value;
        abc$x = x;
        abc$y = y;
        abc$pad = pad;
        abc$invalid = invalid;
        abc$sr = sr;
        abc$er = er;
        abc$at_edge = at_edge;
        abc$face = face;
        abc$base_x = base_x;
        abc$base_y = base_y;
        abc$dx_neg = dx_neg;
        abc$dx_mag = dx_mag;
        abc$dy_neg = dy_neg;
        abc$dy_mag = dy_mag;
        abc$from_left_xm = g_from_left_xm;
        abc$from_left_ym = g_from_left_ym;
        abc$from_left_zm = g_from_left_zm;
        abc$from_right_xp = g_from_right_xp;
        abc$from_right_yp = g_from_right_yp;
        abc$from_right_zp = g_from_right_zp;
        g_to_right_xm = abc$to_right_xm;
        g_to_right_ym = abc$to_right_ym;
        g_to_right_zm = abc$to_right_zm;
        g_to_left_xp = abc$to_left_xp;
        g_to_left_yp = abc$to_left_yp;
        g_to_left_zp = abc$to_left_zp;
        if (use_gradient) begin
            st_valid = abc$o_valid;
            st_value = abc$o_value;
            st_x = abc$o_x;
            st_y = abc$o_y;
            st_pad = abc$o_pad;
            st_invalid = abc$o_invalid;
            st_sr = abc$o_sr;
            st_er = abc$o_er;
            st_edge = abc$o_edge;
            st_face = abc$o_face;
            st_bx = abc$o_base_x;
            st_by = abc$o_base_y;
            st_dxn = abc$o_dx_neg;
            st_dxm = abc$o_dx_mag;
            st_dyn = abc$o_dy_neg;
            st_dym = abc$o_dy_mag;
        end
        else begin
            st_valid = beat_valid;
            st_value = value;
            st_x = x;
            st_y = y;
            st_pad = pad;
            st_invalid = invalid;
            st_sr = sr;
            st_er = er;
            st_edge = at_edge;
            st_face = face;
            st_bx = base_x;
            st_by = base_y;
            st_dxn = dx_neg;
            st_dxm = dx_mag;
            st_dyn = dy_neg;
            st_dym = dy_mag;
        end
        shader$value = st_value;
        shader$invalid = st_invalid;
        shader$at_edge = st_edge;
        shader$gx_neg = abc$gx_neg;
        shader$gx_mag = abc$gx_mag;
        shader$gy_neg = abc$gy_neg;
        shader$gy_mag = abc$gy_mag;
        shader$gz_neg = abc$gz_neg;
        shader$gz_mag = abc$gz_mag;
        v_q$0$d = st_valid;
        er_q$0$d = st_er;
        pad_q$0$d = st_pad;
        bx_q$0$d = st_bx;
        by_q$0$d = st_by;
        face_q$0$d = st_face;
        v_q$1$d = v_q$0$q;
        er_q$1$d = er_q$0$q;
        pad_q$1$d = pad_q$0$q;
        bx_q$1$d = bx_q$0$q;
        by_q$1$d = by_q$0$q;
        face_q$1$d = face_q$0$q;
        v_q$2$d = v_q$1$q;
        er_q$2$d = er_q$1$q;
        pad_q$2$d = pad_q$1$q;
        bx_q$2$d = bx_q$1$q;
        by_q$2$d = by_q$1$q;
        face_q$2$d = face_q$1$q;
        v_q$3$d = v_q$2$q;
        er_q$3$d = er_q$2$q;
        pad_q$3$d = pad_q$2$q;
        bx_q$3$d = bx_q$2$q;
        by_q$3$d = by_q$2$q;
        face_q$3$d = face_q$2$q;
        x_q$d = st_x;
        y_q$d = st_y;
        sr_q$d = st_sr;
        dxn_q$d = st_dxn;
        dxm_q$d = st_dxm;
        dyn_q$d = st_dyn;
        dym_q$d = st_dym;
        first = (x_q$q & p_mask) == 'h0;
        last = (x_q$q & p_mask) == p_mask;
        ring0$read_clock = clock;
        ring0$write_clock = clock;
        ring0$read_address = now + off0;
        t0s0 = ring0$read_data;
        f0_1$d = t0i1;
        s0 = ring0$read_data;
        if (hops0 == 'h1) begin
            s0 = f0_1$q;
        end
        prev0$d = s0;
        a0 = s0;
        ring1$read_clock = clock;
        ring1$write_clock = clock;
        ring1$read_address = now + off1;
        t1s0 = ring1$read_data;
        f1_1$d = t1i1;
        f1_2$d = t1i2;
        t1s1 = f1_1$q;
        s1 = ring1$read_data;
        if (hops1 == 'h1) begin
            s1 = f1_1$q;
        end
        if (hops1 == 'h2) begin
            s1 = f1_2$q;
        end
        prev1$d = s1;
        a1 = s1;
        if (first) begin
            a1 = prev1$q;
        end
        ring2$read_clock = clock;
        ring2$write_clock = clock;
        ring2$read_address = now + off2;
        s2 = ring2$read_data;
        prev2$d = s2;
        a2 = prev2$q;
        if (last) begin
            a2 = s2;
        end
        ring3$read_clock = clock;
        ring3$write_clock = clock;
        ring3$read_address = now + off3;
        t3s0 = ring3$read_data;
        f3_1$d = t3i1;
        f3_2$d = t3i2;
        t3s1 = f3_1$q;
        s3 = ring3$read_data;
        if (hops3 == 'h1) begin
            s3 = f3_1$q;
        end
        if (hops3 == 'h2) begin
            s3 = f3_2$q;
        end
        prev3$d = s3;
        a3 = s3;
        ring4$read_clock = clock;
        ring4$write_clock = clock;
        ring4$read_address = now + off4;
        s4 = ring4$read_data;
        prev4$d = s4;
        a4 = s4;
        ring5$read_clock = clock;
        ring5$write_clock = clock;
        ring5$read_address = now + off5;
        t5s0 = ring5$read_data;
        f5_1$d = t5i1;
        f5_2$d = t5i2;
        f5_3$d = t5i3;
        t5s1 = f5_1$q;
        t5s2 = f5_2$q;
        s5 = ring5$read_data;
        if (hops5 == 'h1) begin
            s5 = f5_1$q;
        end
        if (hops5 == 'h2) begin
            s5 = f5_2$q;
        end
        if (hops5 == 'h3) begin
            s5 = f5_3$q;
        end
        prev5$d = s5;
        a5 = s5;
        if (first) begin
            a5 = prev5$q;
        end
        ring6$read_clock = clock;
        ring6$write_clock = clock;
        ring6$read_address = now + off6;
        t6s0 = ring6$read_data;
        f6_1$d = t6i1;
        s6 = ring6$read_data;
        if (hops6 == 'h1) begin
            s6 = f6_1$q;
        end
        prev6$d = s6;
        a6 = prev6$q;
        if (last) begin
            a6 = s6;
        end
        ring7$read_clock = clock;
        ring7$write_clock = clock;
        ring7$read_address = now + off7;
        t7s0 = ring7$read_data;
        f7_1$d = t7i1;
        s7 = ring7$read_data;
        if (hops7 == 'h1) begin
            s7 = f7_1$q;
        end
        prev7$d = s7;
        a7 = s7;
        if (first) begin
            a7 = prev7$q;
        end
        ring8$read_clock = clock;
        ring8$write_clock = clock;
        ring8$read_address = now + off8;
        t8s0 = ring8$read_data;
        f8_1$d = t8i1;
        s8 = ring8$read_data;
        if (hops8 == 'h1) begin
            s8 = f8_1$q;
        end
        f8l$d = t8il;
        if (left8) begin
            s8 = f8l$q;
        end
        prev8$d = s8;
        a8 = prev8$q;
        if (last) begin
            a8 = s8;
        end
        c00 = a0;
        c10 = a0;
        c01 = a0;
        c11 = a0;
        x_out = 1'b0;
        y_out = 1'b0;
        if (dxm_q$q != 'h0) begin
            if (dxn_q$q) begin
                c10 = a2;
                x_out = x_q$q == nx_last;
            end
            else begin
                c10 = a1;
                x_out = x_q$q == 'h0;
            end
        end
        if (dym_q$q != 'h0) begin
            if (dyn_q$q) begin
                c01 = a4;
                y_out = y_q$q == ny_last;
            end
            else begin
                c01 = a3;
                y_out = y_q$q == 'h0;
            end
        end
        c11 = c01;
        if (dxm_q$q != 'h0) begin
            c11 = c10;
            if (dym_q$q != 'h0) begin
                if (dxn_q$q) begin
                    if (dyn_q$q) begin
                        c11 = a8;
                    end
                    else begin
                        c11 = a6;
                    end
                end
                else if (dyn_q$q) begin
                    c11 = a7;
                end
                else begin
                    c11 = a5;
                end
            end
        end
        if (x_out) begin
            c10 = reset;
            c11 = reset;
        end
        if (y_out) begin
            c01 = reset;
            c11 = reset;
        end
        if (sr_q$q) begin
            c00 = reset;
            c10 = reset;
            c01 = reset;
            c11 = reset;
        end
        bilinear$c00$0 = 32'(c00 & r_mask);
        bilinear$c00$1 = 32'((c00 >> 'h10) & gba_mask);
        bilinear$c00$2 = 32'((c00 >> 'h20) & gba_mask);
        bilinear$c00$3 = 32'((c00 >> 'h30) & gba_mask);
        bilinear$c10$0 = 32'(c10 & r_mask);
        bilinear$c10$1 = 32'((c10 >> 'h10) & gba_mask);
        bilinear$c10$2 = 32'((c10 >> 'h20) & gba_mask);
        bilinear$c10$3 = 32'((c10 >> 'h30) & gba_mask);
        bilinear$c01$0 = 32'(c01 & r_mask);
        bilinear$c01$1 = 32'((c01 >> 'h10) & gba_mask);
        bilinear$c01$2 = 32'((c01 >> 'h20) & gba_mask);
        bilinear$c01$3 = 32'((c01 >> 'h30) & gba_mask);
        bilinear$c11$0 = 32'(c11 & r_mask);
        bilinear$c11$1 = 32'((c11 >> 'h10) & gba_mask);
        bilinear$c11$2 = 32'((c11 >> 'h20) & gba_mask);
        bilinear$c11$3 = 32'((c11 >> 'h30) & gba_mask);
        bilinear$wx = dxm_q$q;
        bilinear$wy = dym_q$q;
        s_r$0$d = shader$r;
        s_g$0$d = shader$g;
        s_b$0$d = shader$b;
        s_a$0$d = shader$a;
        s_v$0$d = shader$valid;
        s_r$1$d = s_r$0$q;
        s_g$1$d = s_g$0$q;
        s_b$1$d = s_b$0$q;
        s_a$1$d = s_a$0$q;
        s_v$1$d = s_v$0$q;
        compositor$acc_r = bilinear$out$0;
        compositor$acc_g = 16'(bilinear$out$1);
        compositor$acc_b = 16'(bilinear$out$2);
        compositor$acc_a = 16'(bilinear$out$3);
        compositor$new_r = 32'(s_r$1$q);
        compositor$new_g = s_g$1$q;
        compositor$new_b = s_b$1$q;
        compositor$new_a = s_a$1$q;
        compositor$new_valid = s_v$1$q;
        res = 64'(compositor$out_r) | (64'(compositor$out_g) << 'h10) | (64'(compositor$out_b) << 'h20) | (64'(compositor$out_a) << 'h30);
        ring0$write_address = now - 'h3;
        ring0$write_data = res;
        ring0$write_enable = v_q$3$q;
        ring1$write_address = now - 'h3;
        ring1$write_data = res;
        ring1$write_enable = v_q$3$q;
        ring2$write_address = now - 'h3;
        ring2$write_data = res;
        ring2$write_enable = v_q$3$q;
        ring3$write_address = now - 'h3;
        ring3$write_data = res;
        ring3$write_enable = v_q$3$q;
        ring4$write_address = now - 'h3;
        ring4$write_data = res;
        ring4$write_enable = v_q$3$q;
        ring5$write_address = now - 'h3;
        ring5$write_data = res;
        ring5$write_enable = v_q$3$q;
        ring6$write_address = now - 'h3;
        ring6$write_data = res;
        ring6$write_enable = v_q$3$q;
        ring7$write_address = now - 'h3;
        ring7$write_data = res;
        ring7$write_enable = v_q$3$q;
        ring8$write_address = now - 'h3;
        ring8$write_data = res;
        ring8$write_enable = v_q$3$q;
        res_beat = v_q$3$q;
        res_valid = v_q$3$q & ~pad_q$3$q;
        px_valid = v_q$3$q & er_q$3$q & ~pad_q$3$q;
        px_x = bx_q$3$q;
        px_y = by_q$3$q;
        px_face = face_q$3$q;
    end
    
endmodule // top$lanes$1
module top$lanes$1$bx_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$1$bx_q$0
module top$lanes$1$bx_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$1$bx_q$1
module top$lanes$1$bx_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$1$bx_q$2
module top$lanes$1$bx_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$1$bx_q$3
module top$lanes$1$by_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$1$by_q$0
module top$lanes$1$by_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$1$by_q$1
module top$lanes$1$by_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$1$by_q$2
module top$lanes$1$by_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$1$by_q$3
module top$lanes$1$dxm_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$dxm_q
module top$lanes$1$dxn_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$dxn_q
module top$lanes$1$dym_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$dym_q
module top$lanes$1$dyn_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$dyn_q
module top$lanes$1$er_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$1$er_q$0
module top$lanes$1$er_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$1$er_q$1
module top$lanes$1$er_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$1$er_q$2
module top$lanes$1$er_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$1$er_q$3
module top$lanes$1$f0_1(d,q,clock);
    
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
          
endmodule // top$lanes$1$f0_1
module top$lanes$1$f1_1(d,q,clock);
    
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
          
endmodule // top$lanes$1$f1_1
module top$lanes$1$f1_2(d,q,clock);
    
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
          
endmodule // top$lanes$1$f1_2
module top$lanes$1$f3_1(d,q,clock);
    
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
          
endmodule // top$lanes$1$f3_1
module top$lanes$1$f3_2(d,q,clock);
    
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
          
endmodule // top$lanes$1$f3_2
module top$lanes$1$f5_1(d,q,clock);
    
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
          
endmodule // top$lanes$1$f5_1
module top$lanes$1$f5_2(d,q,clock);
    
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
          
endmodule // top$lanes$1$f5_2
module top$lanes$1$f5_3(d,q,clock);
    
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
          
endmodule // top$lanes$1$f5_3
module top$lanes$1$f6_1(d,q,clock);
    
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
          
endmodule // top$lanes$1$f6_1
module top$lanes$1$f7_1(d,q,clock);
    
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
          
endmodule // top$lanes$1$f7_1
module top$lanes$1$f8_1(d,q,clock);
    
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
          
endmodule // top$lanes$1$f8_1
module top$lanes$1$f8l(d,q,clock);
    
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
          
endmodule // top$lanes$1$f8l
module top$lanes$1$face_q$0(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$face_q$0
module top$lanes$1$face_q$1(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$face_q$1
module top$lanes$1$face_q$2(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$face_q$2
module top$lanes$1$face_q$3(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$face_q$3
module top$lanes$1$pad_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$1$pad_q$0
module top$lanes$1$pad_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$1$pad_q$1
module top$lanes$1$pad_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$1$pad_q$2
module top$lanes$1$pad_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$1$pad_q$3
module top$lanes$1$prev0(d,q,clock);
    
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
          
endmodule // top$lanes$1$prev0
module top$lanes$1$prev1(d,q,clock);
    
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
          
endmodule // top$lanes$1$prev1
module top$lanes$1$prev2(d,q,clock);
    
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
          
endmodule // top$lanes$1$prev2
module top$lanes$1$prev3(d,q,clock);
    
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
          
endmodule // top$lanes$1$prev3
module top$lanes$1$prev4(d,q,clock);
    
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
          
endmodule // top$lanes$1$prev4
module top$lanes$1$prev5(d,q,clock);
    
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
          
endmodule // top$lanes$1$prev5
module top$lanes$1$prev6(d,q,clock);
    
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
          
endmodule // top$lanes$1$prev6
module top$lanes$1$prev7(d,q,clock);
    
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
          
endmodule // top$lanes$1$prev7
module top$lanes$1$prev8(d,q,clock);
    
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
          
endmodule // top$lanes$1$prev8
module top$lanes$1$ring0(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[2047:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[10:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[10:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$1$ring0
module top$lanes$1$ring1(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[1:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[0:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[0:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$1$ring1
module top$lanes$1$ring2(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[2047:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[10:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[10:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$1$ring2
module top$lanes$1$ring3(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[2047:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[10:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[10:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$1$ring3
module top$lanes$1$ring4(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[1:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[0:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[0:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$1$ring4
module top$lanes$1$ring5(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[1:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[0:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[0:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$1$ring5
module top$lanes$1$ring6(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[2047:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[10:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[10:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$1$ring6
module top$lanes$1$ring7(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[1:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[0:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[0:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$1$ring7
module top$lanes$1$ring8(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[1:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[0:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[0:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$1$ring8
module top$lanes$1$s_a$0(d,q,clock);
    
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
          
endmodule // top$lanes$1$s_a$0
module top$lanes$1$s_a$1(d,q,clock);
    
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
          
endmodule // top$lanes$1$s_a$1
module top$lanes$1$s_b$0(d,q,clock);
    
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
          
endmodule // top$lanes$1$s_b$0
module top$lanes$1$s_b$1(d,q,clock);
    
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
          
endmodule // top$lanes$1$s_b$1
module top$lanes$1$s_g$0(d,q,clock);
    
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
          
endmodule // top$lanes$1$s_g$0
module top$lanes$1$s_g$1(d,q,clock);
    
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
          
endmodule // top$lanes$1$s_g$1
module top$lanes$1$s_r$0(d,q,clock);
    
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
          
endmodule // top$lanes$1$s_r$0
module top$lanes$1$s_r$1(d,q,clock);
    
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
          
endmodule // top$lanes$1$s_r$1
module top$lanes$1$s_v$0(d,q,clock);
    
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
          
endmodule // top$lanes$1$s_v$0
module top$lanes$1$s_v$1(d,q,clock);
    
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
          
endmodule // top$lanes$1$s_v$1
module top$lanes$1$sr_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$sr_q
module top$lanes$1$v_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$1$v_q$0
module top$lanes$1$v_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$1$v_q$1
module top$lanes$1$v_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$1$v_q$2
module top$lanes$1$v_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$1$v_q$3
module top$lanes$1$x_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$x_q
module top$lanes$1$y_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$y_q
module top$lanes$2(clock,now,beat_valid,value,x,y,pad,invalid,halo,sr,er,base_x,base_y,face,at_edge,dx_neg,dx_mag,dy_neg,dy_mag,g_from_left_xm,g_from_left_ym,g_from_left_zm,g_from_right_xp,g_from_right_yp,g_from_right_zp,g_to_right_xm,g_to_right_ym,g_to_right_zm,g_to_left_xp,g_to_left_yp,g_to_left_zp,t0s0,t0i1,t1s0,t1s1,t1i1,t1i2,t3s0,t3s1,t3i1,t3i2,t5s0,t5s1,t5s2,t5i1,t5i2,t5i3,t6s0,t6i1,t7s0,t7i1,t8s0,t8i1,t8il,res_beat,res_valid,res,px_valid,px_x,px_y,px_face);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] now;
    input wire  beat_valid;
    input wire  [15:0] value;
    input wire  [15:0] x;
    input wire  [15:0] y;
    input wire  pad;
    input wire  invalid;
    input wire  halo;
    input wire  sr;
    input wire  er;
    input wire  [15:0] base_x;
    input wire  [15:0] base_y;
    input wire  [2:0] face;
    input wire  at_edge;
    input wire  dx_neg;
    input wire  [15:0] dx_mag;
    input wire  dy_neg;
    input wire  [15:0] dy_mag;
    input wire  [15:0] g_from_left_xm;
    input wire  [15:0] g_from_left_ym;
    input wire  [15:0] g_from_left_zm;
    input wire  [15:0] g_from_right_xp;
    input wire  [15:0] g_from_right_yp;
    input wire  [15:0] g_from_right_zp;
    output reg  [15:0] g_to_right_xm;
    output reg  [15:0] g_to_right_ym;
    output reg  [15:0] g_to_right_zm;
    output reg  [15:0] g_to_left_xp;
    output reg  [15:0] g_to_left_yp;
    output reg  [15:0] g_to_left_zp;
    output reg  [63:0] t0s0;
    input wire  [63:0] t0i1;
    output reg  [63:0] t1s0;
    output reg  [63:0] t1s1;
    input wire  [63:0] t1i1;
    input wire  [63:0] t1i2;
    output reg  [63:0] t3s0;
    output reg  [63:0] t3s1;
    input wire  [63:0] t3i1;
    input wire  [63:0] t3i2;
    output reg  [63:0] t5s0;
    output reg  [63:0] t5s1;
    output reg  [63:0] t5s2;
    input wire  [63:0] t5i1;
    input wire  [63:0] t5i2;
    input wire  [63:0] t5i3;
    output reg  [63:0] t6s0;
    input wire  [63:0] t6i1;
    output reg  [63:0] t7s0;
    input wire  [63:0] t7i1;
    output reg  [63:0] t8s0;
    input wire  [63:0] t8i1;
    input wire  [63:0] t8il;
    output reg  res_beat;
    output reg  res_valid;
    output reg  [63:0] res;
    output reg  px_valid;
    output reg  [15:0] px_x;
    output reg  [15:0] px_y;
    output reg  [2:0] px_face;
    
    // Constant declarations
    localparam  use_gradient = 1'b0;
    localparam  hops0 = 2'b1;
    localparam  off0 = 16'hfc02;
    localparam  hops1 = 2'b10;
    localparam  off1 = 16'hfc03;
    localparam  off2 = 16'hfc02;
    localparam  hops3 = 2'b10;
    localparam  off3 = 16'hfbf3;
    localparam  off4 = 16'hfc11;
    localparam  hops5 = 2'b11;
    localparam  off5 = 16'hfbf4;
    localparam  hops6 = 2'b1;
    localparam  off6 = 16'hfbf3;
    localparam  hops7 = 2'b1;
    localparam  off7 = 16'hfc12;
    localparam  hops8 = 2'b1;
    localparam  off8 = 16'hfc13;
    localparam  left8 = 1'b1;
    localparam  p_mask = 16'h3;
    localparam  nx_last = 16'h3f;
    localparam  ny_last = 16'h3f;
    localparam  reset = 64'h0;
    localparam  r_mask = 64'hffff;
    localparam  gba_mask = 64'hffff;
    
    // Stub signals
    reg  abc$clock;
    reg  [15:0] abc$now;
    reg  abc$valid;
    reg  [15:0] abc$value;
    reg  [15:0] abc$x;
    reg  [15:0] abc$y;
    reg  abc$pad;
    reg  abc$invalid;
    reg  abc$dx_neg;
    reg  [15:0] abc$dx_mag;
    reg  abc$dy_neg;
    reg  [15:0] abc$dy_mag;
    reg  abc$sr;
    reg  abc$er;
    reg  abc$at_edge;
    reg  [2:0] abc$face;
    reg  [15:0] abc$base_x;
    reg  [15:0] abc$base_y;
    reg  [15:0] abc$from_left_xm;
    reg  [15:0] abc$from_left_ym;
    reg  [15:0] abc$from_left_zm;
    reg  [15:0] abc$from_right_xp;
    reg  [15:0] abc$from_right_yp;
    reg  [15:0] abc$from_right_zp;
    wire  [15:0] abc$to_right_xm = 'h0;
    wire  [15:0] abc$to_right_ym = 'h0;
    wire  [15:0] abc$to_right_zm = 'h0;
    wire  [15:0] abc$to_left_xp = 'h0;
    wire  [15:0] abc$to_left_yp = 'h0;
    wire  [15:0] abc$to_left_zp = 'h0;
    wire  abc$o_valid = 'h0;
    wire  [15:0] abc$o_value = 'h0;
    wire  [15:0] abc$o_x = 'h0;
    wire  [15:0] abc$o_y = 'h0;
    wire  abc$o_pad = 'h0;
    wire  abc$o_invalid = 'h0;
    wire  abc$o_dx_neg = 'h0;
    wire  [15:0] abc$o_dx_mag = 'h0;
    wire  abc$o_dy_neg = 'h0;
    wire  [15:0] abc$o_dy_mag = 'h0;
    wire  abc$o_sr = 'h0;
    wire  abc$o_er = 'h0;
    wire  abc$o_edge = 'h0;
    wire  [2:0] abc$o_face = 'h0;
    wire  [15:0] abc$o_base_x = 'h0;
    wire  [15:0] abc$o_base_y = 'h0;
    wire  abc$gx_neg = 'h0;
    wire  [15:0] abc$gx_mag = 'h0;
    wire  abc$gy_neg = 'h0;
    wire  [15:0] abc$gy_mag = 'h0;
    wire  abc$gz_neg = 'h0;
    wire  [15:0] abc$gz_mag = 'h0;
    reg  shader$clock;
    reg  [15:0] shader$value;
    reg  shader$invalid;
    reg  shader$at_edge;
    reg  shader$gx_neg;
    reg  [15:0] shader$gx_mag;
    reg  shader$gy_neg;
    reg  [15:0] shader$gy_mag;
    reg  shader$gz_neg;
    reg  [15:0] shader$gz_mag;
    wire  [15:0] shader$r;
    wire  [15:0] shader$g;
    wire  [15:0] shader$b;
    wire  [15:0] shader$a;
    wire  shader$valid;
    reg  [15:0] ring0$read_address;
    reg  ring0$read_clock;
    wire  [63:0] ring0$read_data;
    reg  [15:0] ring0$write_address;
    reg  ring0$write_clock;
    reg  [63:0] ring0$write_data;
    reg  ring0$write_enable;
    reg  [63:0] f0_1$d;
    wire  [63:0] f0_1$q;
    reg  f0_1$clock;
    reg  [63:0] prev0$d;
    wire  [63:0] prev0$q;
    reg  prev0$clock;
    reg  [15:0] ring1$read_address;
    reg  ring1$read_clock;
    wire  [63:0] ring1$read_data;
    reg  [15:0] ring1$write_address;
    reg  ring1$write_clock;
    reg  [63:0] ring1$write_data;
    reg  ring1$write_enable;
    reg  [63:0] f1_1$d;
    wire  [63:0] f1_1$q;
    reg  f1_1$clock;
    reg  [63:0] f1_2$d;
    wire  [63:0] f1_2$q;
    reg  f1_2$clock;
    reg  [63:0] prev1$d;
    wire  [63:0] prev1$q;
    reg  prev1$clock;
    reg  [15:0] ring2$read_address;
    reg  ring2$read_clock;
    wire  [63:0] ring2$read_data;
    reg  [15:0] ring2$write_address;
    reg  ring2$write_clock;
    reg  [63:0] ring2$write_data;
    reg  ring2$write_enable;
    reg  [63:0] prev2$d;
    wire  [63:0] prev2$q;
    reg  prev2$clock;
    reg  [15:0] ring3$read_address;
    reg  ring3$read_clock;
    wire  [63:0] ring3$read_data;
    reg  [15:0] ring3$write_address;
    reg  ring3$write_clock;
    reg  [63:0] ring3$write_data;
    reg  ring3$write_enable;
    reg  [63:0] f3_1$d;
    wire  [63:0] f3_1$q;
    reg  f3_1$clock;
    reg  [63:0] f3_2$d;
    wire  [63:0] f3_2$q;
    reg  f3_2$clock;
    reg  [63:0] prev3$d;
    wire  [63:0] prev3$q;
    reg  prev3$clock;
    reg  [15:0] ring4$read_address;
    reg  ring4$read_clock;
    wire  [63:0] ring4$read_data;
    reg  [15:0] ring4$write_address;
    reg  ring4$write_clock;
    reg  [63:0] ring4$write_data;
    reg  ring4$write_enable;
    reg  [63:0] prev4$d;
    wire  [63:0] prev4$q;
    reg  prev4$clock;
    reg  [15:0] ring5$read_address;
    reg  ring5$read_clock;
    wire  [63:0] ring5$read_data;
    reg  [15:0] ring5$write_address;
    reg  ring5$write_clock;
    reg  [63:0] ring5$write_data;
    reg  ring5$write_enable;
    reg  [63:0] f5_1$d;
    wire  [63:0] f5_1$q;
    reg  f5_1$clock;
    reg  [63:0] f5_2$d;
    wire  [63:0] f5_2$q;
    reg  f5_2$clock;
    reg  [63:0] f5_3$d;
    wire  [63:0] f5_3$q;
    reg  f5_3$clock;
    reg  [63:0] prev5$d;
    wire  [63:0] prev5$q;
    reg  prev5$clock;
    reg  [15:0] ring6$read_address;
    reg  ring6$read_clock;
    wire  [63:0] ring6$read_data;
    reg  [15:0] ring6$write_address;
    reg  ring6$write_clock;
    reg  [63:0] ring6$write_data;
    reg  ring6$write_enable;
    reg  [63:0] f6_1$d;
    wire  [63:0] f6_1$q;
    reg  f6_1$clock;
    reg  [63:0] prev6$d;
    wire  [63:0] prev6$q;
    reg  prev6$clock;
    reg  [15:0] ring7$read_address;
    reg  ring7$read_clock;
    wire  [63:0] ring7$read_data;
    reg  [15:0] ring7$write_address;
    reg  ring7$write_clock;
    reg  [63:0] ring7$write_data;
    reg  ring7$write_enable;
    reg  [63:0] f7_1$d;
    wire  [63:0] f7_1$q;
    reg  f7_1$clock;
    reg  [63:0] prev7$d;
    wire  [63:0] prev7$q;
    reg  prev7$clock;
    reg  [15:0] ring8$read_address;
    reg  ring8$read_clock;
    wire  [63:0] ring8$read_data;
    reg  [15:0] ring8$write_address;
    reg  ring8$write_clock;
    reg  [63:0] ring8$write_data;
    reg  ring8$write_enable;
    reg  [63:0] f8_1$d;
    wire  [63:0] f8_1$q;
    reg  f8_1$clock;
    reg  [63:0] prev8$d;
    wire  [63:0] prev8$q;
    reg  prev8$clock;
    reg  [63:0] f8l$d;
    wire  [63:0] f8l$q;
    reg  f8l$clock;
    reg  bilinear$clock;
    reg  [31:0] bilinear$c00$0;
    reg  [31:0] bilinear$c00$1;
    reg  [31:0] bilinear$c00$2;
    reg  [31:0] bilinear$c00$3;
    reg  [31:0] bilinear$c10$0;
    reg  [31:0] bilinear$c10$1;
    reg  [31:0] bilinear$c10$2;
    reg  [31:0] bilinear$c10$3;
    reg  [31:0] bilinear$c01$0;
    reg  [31:0] bilinear$c01$1;
    reg  [31:0] bilinear$c01$2;
    reg  [31:0] bilinear$c01$3;
    reg  [31:0] bilinear$c11$0;
    reg  [31:0] bilinear$c11$1;
    reg  [31:0] bilinear$c11$2;
    reg  [31:0] bilinear$c11$3;
    reg  [15:0] bilinear$wx;
    reg  [15:0] bilinear$wy;
    wire  [31:0] bilinear$out$0;
    wire  [31:0] bilinear$out$1;
    wire  [31:0] bilinear$out$2;
    wire  [31:0] bilinear$out$3;
    reg  compositor$clock;
    reg  [31:0] compositor$acc_r;
    reg  [15:0] compositor$acc_g;
    reg  [15:0] compositor$acc_b;
    reg  [15:0] compositor$acc_a;
    reg  [31:0] compositor$new_r;
    reg  [15:0] compositor$new_g;
    reg  [15:0] compositor$new_b;
    reg  [15:0] compositor$new_a;
    reg  compositor$new_valid;
    wire  [31:0] compositor$out_r;
    wire  [15:0] compositor$out_g;
    wire  [15:0] compositor$out_b;
    wire  [15:0] compositor$out_a;
    reg  v_q$0$d;
    wire  v_q$0$q;
    reg  v_q$0$clock;
    reg  v_q$1$d;
    wire  v_q$1$q;
    reg  v_q$1$clock;
    reg  v_q$2$d;
    wire  v_q$2$q;
    reg  v_q$2$clock;
    reg  v_q$3$d;
    wire  v_q$3$q;
    reg  v_q$3$clock;
    reg  er_q$0$d;
    wire  er_q$0$q;
    reg  er_q$0$clock;
    reg  er_q$1$d;
    wire  er_q$1$q;
    reg  er_q$1$clock;
    reg  er_q$2$d;
    wire  er_q$2$q;
    reg  er_q$2$clock;
    reg  er_q$3$d;
    wire  er_q$3$q;
    reg  er_q$3$clock;
    reg  pad_q$0$d;
    wire  pad_q$0$q;
    reg  pad_q$0$clock;
    reg  pad_q$1$d;
    wire  pad_q$1$q;
    reg  pad_q$1$clock;
    reg  pad_q$2$d;
    wire  pad_q$2$q;
    reg  pad_q$2$clock;
    reg  pad_q$3$d;
    wire  pad_q$3$q;
    reg  pad_q$3$clock;
    reg  [15:0] bx_q$0$d;
    wire  [15:0] bx_q$0$q;
    reg  bx_q$0$clock;
    reg  [15:0] bx_q$1$d;
    wire  [15:0] bx_q$1$q;
    reg  bx_q$1$clock;
    reg  [15:0] bx_q$2$d;
    wire  [15:0] bx_q$2$q;
    reg  bx_q$2$clock;
    reg  [15:0] bx_q$3$d;
    wire  [15:0] bx_q$3$q;
    reg  bx_q$3$clock;
    reg  [15:0] by_q$0$d;
    wire  [15:0] by_q$0$q;
    reg  by_q$0$clock;
    reg  [15:0] by_q$1$d;
    wire  [15:0] by_q$1$q;
    reg  by_q$1$clock;
    reg  [15:0] by_q$2$d;
    wire  [15:0] by_q$2$q;
    reg  by_q$2$clock;
    reg  [15:0] by_q$3$d;
    wire  [15:0] by_q$3$q;
    reg  by_q$3$clock;
    reg  [2:0] face_q$0$d;
    wire  [2:0] face_q$0$q;
    reg  face_q$0$clock;
    reg  [2:0] face_q$1$d;
    wire  [2:0] face_q$1$q;
    reg  face_q$1$clock;
    reg  [2:0] face_q$2$d;
    wire  [2:0] face_q$2$q;
    reg  face_q$2$clock;
    reg  [2:0] face_q$3$d;
    wire  [2:0] face_q$3$q;
    reg  face_q$3$clock;
    reg  [15:0] x_q$d;
    wire  [15:0] x_q$q;
    reg  x_q$clock;
    reg  [15:0] y_q$d;
    wire  [15:0] y_q$q;
    reg  y_q$clock;
    reg  sr_q$d;
    wire  sr_q$q;
    reg  sr_q$clock;
    reg  dxn_q$d;
    wire  dxn_q$q;
    reg  dxn_q$clock;
    reg  [15:0] dxm_q$d;
    wire  [15:0] dxm_q$q;
    reg  dxm_q$clock;
    reg  dyn_q$d;
    wire  dyn_q$q;
    reg  dyn_q$clock;
    reg  [15:0] dym_q$d;
    wire  [15:0] dym_q$q;
    reg  dym_q$clock;
    reg  [15:0] s_r$0$d;
    wire  [15:0] s_r$0$q;
    reg  s_r$0$clock;
    reg  [15:0] s_r$1$d;
    wire  [15:0] s_r$1$q;
    reg  s_r$1$clock;
    reg  [15:0] s_g$0$d;
    wire  [15:0] s_g$0$q;
    reg  s_g$0$clock;
    reg  [15:0] s_g$1$d;
    wire  [15:0] s_g$1$q;
    reg  s_g$1$clock;
    reg  [15:0] s_b$0$d;
    wire  [15:0] s_b$0$q;
    reg  s_b$0$clock;
    reg  [15:0] s_b$1$d;
    wire  [15:0] s_b$1$q;
    reg  s_b$1$clock;
    reg  [15:0] s_a$0$d;
    wire  [15:0] s_a$0$q;
    reg  s_a$0$clock;
    reg  [15:0] s_a$1$d;
    wire  [15:0] s_a$1$q;
    reg  s_a$1$clock;
    reg  s_v$0$d;
    wire  s_v$0$q;
    reg  s_v$0$clock;
    reg  s_v$1$d;
    wire  s_v$1$q;
    reg  s_v$1$clock;
    
    // Local signals
    reg  st_valid;
    reg  [15:0] st_value;
    reg  [15:0] st_x;
    reg  [15:0] st_y;
    reg  st_pad;
    reg  st_invalid;
    reg  st_sr;
    reg  st_er;
    reg  st_edge;
    reg  [2:0] st_face;
    reg  [15:0] st_bx;
    reg  [15:0] st_by;
    reg  st_dxn;
    reg  [15:0] st_dxm;
    reg  st_dyn;
    reg  [15:0] st_dym;
    reg  [63:0] s0;
    reg  [63:0] a0;
    reg  [63:0] s1;
    reg  [63:0] a1;
    reg  [63:0] s2;
    reg  [63:0] a2;
    reg  [63:0] s3;
    reg  [63:0] a3;
    reg  [63:0] s4;
    reg  [63:0] a4;
    reg  [63:0] s5;
    reg  [63:0] a5;
    reg  [63:0] s6;
    reg  [63:0] a6;
    reg  [63:0] s7;
    reg  [63:0] a7;
    reg  [63:0] s8;
    reg  [63:0] a8;
    reg  first;
    reg  last;
    reg  [63:0] c00;
    reg  [63:0] c10;
    reg  [63:0] c01;
    reg  [63:0] c11;
    reg  x_out;
    reg  y_out;
    
    // Sub module instances
    top$lanes$2$shader shader(
        .clock(shader$clock),
        .value(shader$value),
        .invalid(shader$invalid),
        .at_edge(shader$at_edge),
        .gx_neg(shader$gx_neg),
        .gx_mag(shader$gx_mag),
        .gy_neg(shader$gy_neg),
        .gy_mag(shader$gy_mag),
        .gz_neg(shader$gz_neg),
        .gz_mag(shader$gz_mag),
        .r(shader$r),
        .g(shader$g),
        .b(shader$b),
        .a(shader$a),
        .valid(shader$valid)
    );
    top$lanes$2$ring0 ring0(
        .read_address(ring0$read_address),
        .read_clock(ring0$read_clock),
        .read_data(ring0$read_data),
        .write_address(ring0$write_address),
        .write_clock(ring0$write_clock),
        .write_data(ring0$write_data),
        .write_enable(ring0$write_enable)
    );
    top$lanes$2$f0_1 f0_1(
        .d(f0_1$d),
        .q(f0_1$q),
        .clock(f0_1$clock)
    );
    top$lanes$2$prev0 prev0(
        .d(prev0$d),
        .q(prev0$q),
        .clock(prev0$clock)
    );
    top$lanes$2$ring1 ring1(
        .read_address(ring1$read_address),
        .read_clock(ring1$read_clock),
        .read_data(ring1$read_data),
        .write_address(ring1$write_address),
        .write_clock(ring1$write_clock),
        .write_data(ring1$write_data),
        .write_enable(ring1$write_enable)
    );
    top$lanes$2$f1_1 f1_1(
        .d(f1_1$d),
        .q(f1_1$q),
        .clock(f1_1$clock)
    );
    top$lanes$2$f1_2 f1_2(
        .d(f1_2$d),
        .q(f1_2$q),
        .clock(f1_2$clock)
    );
    top$lanes$2$prev1 prev1(
        .d(prev1$d),
        .q(prev1$q),
        .clock(prev1$clock)
    );
    top$lanes$2$ring2 ring2(
        .read_address(ring2$read_address),
        .read_clock(ring2$read_clock),
        .read_data(ring2$read_data),
        .write_address(ring2$write_address),
        .write_clock(ring2$write_clock),
        .write_data(ring2$write_data),
        .write_enable(ring2$write_enable)
    );
    top$lanes$2$prev2 prev2(
        .d(prev2$d),
        .q(prev2$q),
        .clock(prev2$clock)
    );
    top$lanes$2$ring3 ring3(
        .read_address(ring3$read_address),
        .read_clock(ring3$read_clock),
        .read_data(ring3$read_data),
        .write_address(ring3$write_address),
        .write_clock(ring3$write_clock),
        .write_data(ring3$write_data),
        .write_enable(ring3$write_enable)
    );
    top$lanes$2$f3_1 f3_1(
        .d(f3_1$d),
        .q(f3_1$q),
        .clock(f3_1$clock)
    );
    top$lanes$2$f3_2 f3_2(
        .d(f3_2$d),
        .q(f3_2$q),
        .clock(f3_2$clock)
    );
    top$lanes$2$prev3 prev3(
        .d(prev3$d),
        .q(prev3$q),
        .clock(prev3$clock)
    );
    top$lanes$2$ring4 ring4(
        .read_address(ring4$read_address),
        .read_clock(ring4$read_clock),
        .read_data(ring4$read_data),
        .write_address(ring4$write_address),
        .write_clock(ring4$write_clock),
        .write_data(ring4$write_data),
        .write_enable(ring4$write_enable)
    );
    top$lanes$2$prev4 prev4(
        .d(prev4$d),
        .q(prev4$q),
        .clock(prev4$clock)
    );
    top$lanes$2$ring5 ring5(
        .read_address(ring5$read_address),
        .read_clock(ring5$read_clock),
        .read_data(ring5$read_data),
        .write_address(ring5$write_address),
        .write_clock(ring5$write_clock),
        .write_data(ring5$write_data),
        .write_enable(ring5$write_enable)
    );
    top$lanes$2$f5_1 f5_1(
        .d(f5_1$d),
        .q(f5_1$q),
        .clock(f5_1$clock)
    );
    top$lanes$2$f5_2 f5_2(
        .d(f5_2$d),
        .q(f5_2$q),
        .clock(f5_2$clock)
    );
    top$lanes$2$f5_3 f5_3(
        .d(f5_3$d),
        .q(f5_3$q),
        .clock(f5_3$clock)
    );
    top$lanes$2$prev5 prev5(
        .d(prev5$d),
        .q(prev5$q),
        .clock(prev5$clock)
    );
    top$lanes$2$ring6 ring6(
        .read_address(ring6$read_address),
        .read_clock(ring6$read_clock),
        .read_data(ring6$read_data),
        .write_address(ring6$write_address),
        .write_clock(ring6$write_clock),
        .write_data(ring6$write_data),
        .write_enable(ring6$write_enable)
    );
    top$lanes$2$f6_1 f6_1(
        .d(f6_1$d),
        .q(f6_1$q),
        .clock(f6_1$clock)
    );
    top$lanes$2$prev6 prev6(
        .d(prev6$d),
        .q(prev6$q),
        .clock(prev6$clock)
    );
    top$lanes$2$ring7 ring7(
        .read_address(ring7$read_address),
        .read_clock(ring7$read_clock),
        .read_data(ring7$read_data),
        .write_address(ring7$write_address),
        .write_clock(ring7$write_clock),
        .write_data(ring7$write_data),
        .write_enable(ring7$write_enable)
    );
    top$lanes$2$f7_1 f7_1(
        .d(f7_1$d),
        .q(f7_1$q),
        .clock(f7_1$clock)
    );
    top$lanes$2$prev7 prev7(
        .d(prev7$d),
        .q(prev7$q),
        .clock(prev7$clock)
    );
    top$lanes$2$ring8 ring8(
        .read_address(ring8$read_address),
        .read_clock(ring8$read_clock),
        .read_data(ring8$read_data),
        .write_address(ring8$write_address),
        .write_clock(ring8$write_clock),
        .write_data(ring8$write_data),
        .write_enable(ring8$write_enable)
    );
    top$lanes$2$f8_1 f8_1(
        .d(f8_1$d),
        .q(f8_1$q),
        .clock(f8_1$clock)
    );
    top$lanes$2$prev8 prev8(
        .d(prev8$d),
        .q(prev8$q),
        .clock(prev8$clock)
    );
    top$lanes$2$f8l f8l(
        .d(f8l$d),
        .q(f8l$q),
        .clock(f8l$clock)
    );
    top$lanes$2$bilinear bilinear(
        .clock(bilinear$clock),
        .c00$0(bilinear$c00$0),
        .c00$1(bilinear$c00$1),
        .c00$2(bilinear$c00$2),
        .c00$3(bilinear$c00$3),
        .c10$0(bilinear$c10$0),
        .c10$1(bilinear$c10$1),
        .c10$2(bilinear$c10$2),
        .c10$3(bilinear$c10$3),
        .c01$0(bilinear$c01$0),
        .c01$1(bilinear$c01$1),
        .c01$2(bilinear$c01$2),
        .c01$3(bilinear$c01$3),
        .c11$0(bilinear$c11$0),
        .c11$1(bilinear$c11$1),
        .c11$2(bilinear$c11$2),
        .c11$3(bilinear$c11$3),
        .wx(bilinear$wx),
        .wy(bilinear$wy),
        .out$0(bilinear$out$0),
        .out$1(bilinear$out$1),
        .out$2(bilinear$out$2),
        .out$3(bilinear$out$3)
    );
    top$lanes$2$compositor compositor(
        .clock(compositor$clock),
        .acc_r(compositor$acc_r),
        .acc_g(compositor$acc_g),
        .acc_b(compositor$acc_b),
        .acc_a(compositor$acc_a),
        .new_r(compositor$new_r),
        .new_g(compositor$new_g),
        .new_b(compositor$new_b),
        .new_a(compositor$new_a),
        .new_valid(compositor$new_valid),
        .out_r(compositor$out_r),
        .out_g(compositor$out_g),
        .out_b(compositor$out_b),
        .out_a(compositor$out_a)
    );
    top$lanes$2$v_q$0 v_q$0(
        .d(v_q$0$d),
        .q(v_q$0$q),
        .clock(v_q$0$clock)
    );
    top$lanes$2$v_q$1 v_q$1(
        .d(v_q$1$d),
        .q(v_q$1$q),
        .clock(v_q$1$clock)
    );
    top$lanes$2$v_q$2 v_q$2(
        .d(v_q$2$d),
        .q(v_q$2$q),
        .clock(v_q$2$clock)
    );
    top$lanes$2$v_q$3 v_q$3(
        .d(v_q$3$d),
        .q(v_q$3$q),
        .clock(v_q$3$clock)
    );
    top$lanes$2$er_q$0 er_q$0(
        .d(er_q$0$d),
        .q(er_q$0$q),
        .clock(er_q$0$clock)
    );
    top$lanes$2$er_q$1 er_q$1(
        .d(er_q$1$d),
        .q(er_q$1$q),
        .clock(er_q$1$clock)
    );
    top$lanes$2$er_q$2 er_q$2(
        .d(er_q$2$d),
        .q(er_q$2$q),
        .clock(er_q$2$clock)
    );
    top$lanes$2$er_q$3 er_q$3(
        .d(er_q$3$d),
        .q(er_q$3$q),
        .clock(er_q$3$clock)
    );
    top$lanes$2$pad_q$0 pad_q$0(
        .d(pad_q$0$d),
        .q(pad_q$0$q),
        .clock(pad_q$0$clock)
    );
    top$lanes$2$pad_q$1 pad_q$1(
        .d(pad_q$1$d),
        .q(pad_q$1$q),
        .clock(pad_q$1$clock)
    );
    top$lanes$2$pad_q$2 pad_q$2(
        .d(pad_q$2$d),
        .q(pad_q$2$q),
        .clock(pad_q$2$clock)
    );
    top$lanes$2$pad_q$3 pad_q$3(
        .d(pad_q$3$d),
        .q(pad_q$3$q),
        .clock(pad_q$3$clock)
    );
    top$lanes$2$bx_q$0 bx_q$0(
        .d(bx_q$0$d),
        .q(bx_q$0$q),
        .clock(bx_q$0$clock)
    );
    top$lanes$2$bx_q$1 bx_q$1(
        .d(bx_q$1$d),
        .q(bx_q$1$q),
        .clock(bx_q$1$clock)
    );
    top$lanes$2$bx_q$2 bx_q$2(
        .d(bx_q$2$d),
        .q(bx_q$2$q),
        .clock(bx_q$2$clock)
    );
    top$lanes$2$bx_q$3 bx_q$3(
        .d(bx_q$3$d),
        .q(bx_q$3$q),
        .clock(bx_q$3$clock)
    );
    top$lanes$2$by_q$0 by_q$0(
        .d(by_q$0$d),
        .q(by_q$0$q),
        .clock(by_q$0$clock)
    );
    top$lanes$2$by_q$1 by_q$1(
        .d(by_q$1$d),
        .q(by_q$1$q),
        .clock(by_q$1$clock)
    );
    top$lanes$2$by_q$2 by_q$2(
        .d(by_q$2$d),
        .q(by_q$2$q),
        .clock(by_q$2$clock)
    );
    top$lanes$2$by_q$3 by_q$3(
        .d(by_q$3$d),
        .q(by_q$3$q),
        .clock(by_q$3$clock)
    );
    top$lanes$2$face_q$0 face_q$0(
        .d(face_q$0$d),
        .q(face_q$0$q),
        .clock(face_q$0$clock)
    );
    top$lanes$2$face_q$1 face_q$1(
        .d(face_q$1$d),
        .q(face_q$1$q),
        .clock(face_q$1$clock)
    );
    top$lanes$2$face_q$2 face_q$2(
        .d(face_q$2$d),
        .q(face_q$2$q),
        .clock(face_q$2$clock)
    );
    top$lanes$2$face_q$3 face_q$3(
        .d(face_q$3$d),
        .q(face_q$3$q),
        .clock(face_q$3$clock)
    );
    top$lanes$2$x_q x_q(
        .d(x_q$d),
        .q(x_q$q),
        .clock(x_q$clock)
    );
    top$lanes$2$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    top$lanes$2$sr_q sr_q(
        .d(sr_q$d),
        .q(sr_q$q),
        .clock(sr_q$clock)
    );
    top$lanes$2$dxn_q dxn_q(
        .d(dxn_q$d),
        .q(dxn_q$q),
        .clock(dxn_q$clock)
    );
    top$lanes$2$dxm_q dxm_q(
        .d(dxm_q$d),
        .q(dxm_q$q),
        .clock(dxm_q$clock)
    );
    top$lanes$2$dyn_q dyn_q(
        .d(dyn_q$d),
        .q(dyn_q$q),
        .clock(dyn_q$clock)
    );
    top$lanes$2$dym_q dym_q(
        .d(dym_q$d),
        .q(dym_q$q),
        .clock(dym_q$clock)
    );
    top$lanes$2$s_r$0 s_r$0(
        .d(s_r$0$d),
        .q(s_r$0$q),
        .clock(s_r$0$clock)
    );
    top$lanes$2$s_r$1 s_r$1(
        .d(s_r$1$d),
        .q(s_r$1$q),
        .clock(s_r$1$clock)
    );
    top$lanes$2$s_g$0 s_g$0(
        .d(s_g$0$d),
        .q(s_g$0$q),
        .clock(s_g$0$clock)
    );
    top$lanes$2$s_g$1 s_g$1(
        .d(s_g$1$d),
        .q(s_g$1$q),
        .clock(s_g$1$clock)
    );
    top$lanes$2$s_b$0 s_b$0(
        .d(s_b$0$d),
        .q(s_b$0$q),
        .clock(s_b$0$clock)
    );
    top$lanes$2$s_b$1 s_b$1(
        .d(s_b$1$d),
        .q(s_b$1$q),
        .clock(s_b$1$clock)
    );
    top$lanes$2$s_a$0 s_a$0(
        .d(s_a$0$d),
        .q(s_a$0$q),
        .clock(s_a$0$clock)
    );
    top$lanes$2$s_a$1 s_a$1(
        .d(s_a$1$d),
        .q(s_a$1$q),
        .clock(s_a$1$clock)
    );
    top$lanes$2$s_v$0 s_v$0(
        .d(s_v$0$d),
        .q(s_v$0$q),
        .clock(s_v$0$clock)
    );
    top$lanes$2$s_v$1 s_v$1(
        .d(s_v$1$d),
        .q(s_v$1$q),
        .clock(s_v$1$clock)
    );
    
    // Update code
    always @(*) begin
        x_q$clock = clock;
        y_q$clock = clock;
        sr_q$clock = clock;
        dxn_q$clock = clock;
        dxm_q$clock = clock;
        dyn_q$clock = clock;
        dym_q$clock = clock;
        f0_1$clock = clock;
        prev0$clock = clock;
        f1_1$clock = clock;
        f1_2$clock = clock;
        prev1$clock = clock;
        prev2$clock = clock;
        f3_1$clock = clock;
        f3_2$clock = clock;
        prev3$clock = clock;
        prev4$clock = clock;
        f5_1$clock = clock;
        f5_2$clock = clock;
        f5_3$clock = clock;
        prev5$clock = clock;
        f6_1$clock = clock;
        prev6$clock = clock;
        f7_1$clock = clock;
        prev7$clock = clock;
        f8_1$clock = clock;
        prev8$clock = clock;
        f8l$clock = clock;
        x_q$d = x_q$q;
        y_q$d = y_q$q;
        sr_q$d = sr_q$q;
        dxn_q$d = dxn_q$q;
        dxm_q$d = dxm_q$q;
        dyn_q$d = dyn_q$q;
        dym_q$d = dym_q$q;
        f0_1$d = f0_1$q;
        prev0$d = prev0$q;
        f1_1$d = f1_1$q;
        f1_2$d = f1_2$q;
        prev1$d = prev1$q;
        prev2$d = prev2$q;
        f3_1$d = f3_1$q;
        f3_2$d = f3_2$q;
        prev3$d = prev3$q;
        prev4$d = prev4$q;
        f5_1$d = f5_1$q;
        f5_2$d = f5_2$q;
        f5_3$d = f5_3$q;
        prev5$d = prev5$q;
        f6_1$d = f6_1$q;
        prev6$d = prev6$q;
        f7_1$d = f7_1$q;
        prev7$d = prev7$q;
        f8_1$d = f8_1$q;
        prev8$d = prev8$q;
        f8l$d = f8l$q;
        v_q$0$clock = clock;
        er_q$0$clock = clock;
        pad_q$0$clock = clock;
        bx_q$0$clock = clock;
        by_q$0$clock = clock;
        face_q$0$clock = clock;
        v_q$1$clock = clock;
        er_q$1$clock = clock;
        pad_q$1$clock = clock;
        bx_q$1$clock = clock;
        by_q$1$clock = clock;
        face_q$1$clock = clock;
        v_q$2$clock = clock;
        er_q$2$clock = clock;
        pad_q$2$clock = clock;
        bx_q$2$clock = clock;
        by_q$2$clock = clock;
        face_q$2$clock = clock;
        v_q$3$clock = clock;
        er_q$3$clock = clock;
        pad_q$3$clock = clock;
        bx_q$3$clock = clock;
        by_q$3$clock = clock;
        face_q$3$clock = clock;
        s_r$0$clock = clock;
        s_g$0$clock = clock;
        s_b$0$clock = clock;
        s_a$0$clock = clock;
        s_v$0$clock = clock;
        s_r$1$clock = clock;
        s_g$1$clock = clock;
        s_b$1$clock = clock;
        s_a$1$clock = clock;
        s_v$1$clock = clock;
        shader$clock = clock;
        bilinear$clock = clock;
        compositor$clock = clock;
        abc$clock = clock;
        abc$now = now;
        abc$valid = beat_valid & ~halo;
        abc$value = value;
        abc$x = x;
        abc$y = y;
        abc$pad = pad;
        abc$invalid = invalid;
        abc$sr = sr;
        abc$er = er;
        abc$at_edge = at_edge;
        abc$face = face;
        abc$base_x = base_x;
        abc$base_y = base_y;
        abc$dx_neg = dx_neg;
        abc$dx_mag = dx_mag;
        abc$dy_neg = dy_neg;
        abc$dy_mag = dy_mag;
        abc$from_left_xm = g_from_left_xm;
        abc$from_left_ym = g_from_left_ym;
        abc$from_left_zm = g_from_left_zm;
        abc$from_right_xp = g_from_right_xp;
        abc$from_right_yp = g_from_right_yp;
        abc$from_right_zp = g_from_right_zp;
        g_to_right_xm = abc$to_right_xm;
        g_to_right_ym = abc$to_right_ym;
        g_to_right_zm = abc$to_right_zm;
        g_to_left_xp = abc$to_left_xp;
        g_to_left_yp = abc$to_left_yp;
        g_to_left_zp = abc$to_left_zp;
        if (use_gradient) begin
            st_valid = abc$o_valid;
            st_value = abc$o_value;
            st_x = abc$o_x;
            st_y = abc$o_y;
            st_pad = abc$o_pad;
            st_invalid = abc$o_invalid;
            st_sr = abc$o_sr;
            st_er = abc$o_er;
            st_edge = abc$o_edge;
            st_face = abc$o_face;
            st_bx = abc$o_base_x;
            st_by = abc$o_base_y;
            st_dxn = abc$o_dx_neg;
            st_dxm = abc$o_dx_mag;
            st_dyn = abc$o_dy_neg;
            st_dym = abc$o_dy_mag;
        end
        else begin
            st_valid = beat_valid;
            st_value = value;
            st_x = x;
            st_y = y;
            st_pad = pad;
            st_invalid = invalid;
            st_sr = sr;
            st_er = er;
            st_edge = at_edge;
            st_face = face;
            st_bx = base_x;
            st_by = base_y;
            st_dxn = dx_neg;
            st_dxm = dx_mag;
            st_dyn = dy_neg;
            st_dym = dy_mag;
        end
        shader$value = st_value;
        shader$invalid = st_invalid;
        shader$at_edge = st_edge;
        shader$gx_neg = abc$gx_neg;
        shader$gx_mag = abc$gx_mag;
        shader$gy_neg = abc$gy_neg;
        shader$gy_mag = abc$gy_mag;
        shader$gz_neg = abc$gz_neg;
        shader$gz_mag = abc$gz_mag;
        v_q$0$d = st_valid;
        er_q$0$d = st_er;
        pad_q$0$d = st_pad;
        bx_q$0$d = st_bx;
        by_q$0$d = st_by;
        face_q$0$d = st_face;
        v_q$1$d = v_q$0$q;
        er_q$1$d = er_q$0$q;
        pad_q$1$d = pad_q$0$q;
        bx_q$1$d = bx_q$0$q;
        by_q$1$d = by_q$0$q;
        face_q$1$d = face_q$0$q;
        v_q$2$d = v_q$1$q;
        er_q$2$d = er_q$1$q;
        pad_q$2$d = pad_q$1$q;
        bx_q$2$d = bx_q$1$q;
        by_q$2$d = by_q$1$q;
        face_q$2$d = face_q$1$q;
        v_q$3$d = v_q$2$q;
        er_q$3$d = er_q$2$q;
        pad_q$3$d = pad_q$2$q;
        bx_q$3$d = bx_q$2$q;
        by_q$3$d = by_q$2$q;
        face_q$3$d = face_q$2$q;
        x_q$d = st_x;
        y_q$d = st_y;
        sr_q$d = st_sr;
        dxn_q$d = st_dxn;
        dxm_q$d = st_dxm;
        dyn_q$d = st_dyn;
        dym_q$d = st_dym;
        first = (x_q$q & p_mask) == 'h0;
        last = (x_q$q & p_mask) == p_mask;
        ring0$read_clock = clock;
        ring0$write_clock = clock;
        ring0$read_address = now + off0;
        t0s0 = ring0$read_data;
        f0_1$d = t0i1;
        s0 = ring0$read_data;
        if (hops0 == 'h1) begin
            s0 = f0_1$q;
        end
        prev0$d = s0;
        a0 = s0;
        ring1$read_clock = clock;
        ring1$write_clock = clock;
        ring1$read_address = now + off1;
        t1s0 = ring1$read_data;
        f1_1$d = t1i1;
        f1_2$d = t1i2;
        t1s1 = f1_1$q;
        s1 = ring1$read_data;
        if (hops1 == 'h1) begin
            s1 = f1_1$q;
        end
        if (hops1 == 'h2) begin
            s1 = f1_2$q;
        end
        prev1$d = s1;
        a1 = s1;
        if (first) begin
            a1 = prev1$q;
        end
        ring2$read_clock = clock;
        ring2$write_clock = clock;
        ring2$read_address = now + off2;
        s2 = ring2$read_data;
        prev2$d = s2;
        a2 = prev2$q;
        if (last) begin
            a2 = s2;
        end
        ring3$read_clock = clock;
        ring3$write_clock = clock;
        ring3$read_address = now + off3;
        t3s0 = ring3$read_data;
        f3_1$d = t3i1;
        f3_2$d = t3i2;
        t3s1 = f3_1$q;
        s3 = ring3$read_data;
        if (hops3 == 'h1) begin
            s3 = f3_1$q;
        end
        if (hops3 == 'h2) begin
            s3 = f3_2$q;
        end
        prev3$d = s3;
        a3 = s3;
        ring4$read_clock = clock;
        ring4$write_clock = clock;
        ring4$read_address = now + off4;
        s4 = ring4$read_data;
        prev4$d = s4;
        a4 = s4;
        ring5$read_clock = clock;
        ring5$write_clock = clock;
        ring5$read_address = now + off5;
        t5s0 = ring5$read_data;
        f5_1$d = t5i1;
        f5_2$d = t5i2;
        f5_3$d = t5i3;
        t5s1 = f5_1$q;
        t5s2 = f5_2$q;
        s5 = ring5$read_data;
        if (hops5 == 'h1) begin
            s5 = f5_1$q;
        end
        if (hops5 == 'h2) begin
            s5 = f5_2$q;
        end
        if (hops5 == 'h3) begin
            s5 = f5_3$q;
        end
        prev5$d = s5;
        a5 = s5;
        if (first) begin
            a5 = prev5$q;
        end
        ring6$read_clock = clock;
        ring6$write_clock = clock;
        ring6$read_address = now + off6;
        t6s0 = ring6$read_data;
        f6_1$d = t6i1;
        s6 = ring6$read_data;
        if (hops6 == 'h1) begin
            s6 = f6_1$q;
        end
        prev6$d = s6;
        a6 = prev6$q;
        if (last) begin
            a6 = s6;
        end
        ring7$read_clock = clock;
        ring7$write_clock = clock;
        ring7$read_address = now + off7;
        t7s0 = ring7$read_data;
        f7_1$d = t7i1;
        s7 = ring7$read_data;
        if (hops7 == 'h1) begin
            s7 = f7_1$q;
        end
        prev7$d = s7;
        a7 = s7;
        if (first) begin
            a7 = prev7$q;
        end
        ring8$read_clock = clock;
        ring8$write_clock = clock;
        ring8$read_address = now + off8;
        t8s0 = ring8$read_data;
        f8_1$d = t8i1;
        s8 = ring8$read_data;
        if (hops8 == 'h1) begin
            s8 = f8_1$q;
        end
        f8l$d = t8il;
        if (left8) begin
            s8 = f8l$q;
        end
        prev8$d = s8;
        a8 = prev8$q;
        if (last) begin
            a8 = s8;
        end
        c00 = a0;
        c10 = a0;
        c01 = a0;
        c11 = a0;
        x_out = 1'b0;
        y_out = 1'b0;
        if (dxm_q$q != 'h0) begin
            if (dxn_q$q) begin
                c10 = a2;
                x_out = x_q$q == nx_last;
            end
            else begin
                c10 = a1;
                x_out = x_q$q == 'h0;
            end
        end
        if (dym_q$q != 'h0) begin
            if (dyn_q$q) begin
                c01 = a4;
                y_out = y_q$q == ny_last;
            end
            else begin
                c01 = a3;
                y_out = y_q$q == 'h0;
            end
        end
        c11 = c01;
        if (dxm_q$q != 'h0) begin
            c11 = c10;
            if (dym_q$q != 'h0) begin
                if (dxn_q$q) begin
                    if (dyn_q$q) begin
                        c11 = a8;
                    end
                    else begin
                        c11 = a6;
                    end
                end
                else if (dyn_q$q) begin
                    c11 = a7;
                end
                else begin
                    c11 = a5;
                end
            end
        end
        if (x_out) begin
            c10 = reset;
            c11 = reset;
        end
        if (y_out) begin
            c01 = reset;
            c11 = reset;
        end
        if (sr_q$q) begin
            c00 = reset;
            c10 = reset;
            c01 = reset;
            c11 = reset;
        end
        bilinear$c00$0 = 32'(c00 & r_mask);
        bilinear$c00$1 = 32'((c00 >> 'h10) & gba_mask);
        bilinear$c00$2 = 32'((c00 >> 'h20) & gba_mask);
        bilinear$c00$3 = 32'((c00 >> 'h30) & gba_mask);
        bilinear$c10$0 = 32'(c10 & r_mask);
        bilinear$c10$1 = 32'((c10 >> 'h10) & gba_mask);
        bilinear$c10$2 = 32'((c10 >> 'h20) & gba_mask);
        bilinear$c10$3 = 32'((c10 >> 'h30) & gba_mask);
        bilinear$c01$0 = 32'(c01 & r_mask);
        bilinear$c01$1 = 32'((c01 >> 'h10) & gba_mask);
        bilinear$c01$2 = 32'((c01 >> 'h20) & gba_mask);
        bilinear$c01$3 = 32'((c01 >> 'h30) & gba_mask);
        bilinear$c11$0 = 32'(c11 & r_mask);
        bilinear$c11$1 = 32'((c11 >> 'h10) & gba_mask);
        bilinear$c11$2 = 32'((c11 >> 'h20) & gba_mask);
        bilinear$c11$3 = 32'((c11 >> 'h30) & gba_mask);
        bilinear$wx = dxm_q$q;
        bilinear$wy = dym_q$q;
        s_r$0$d = shader$r;
        s_g$0$d = shader$g;
        s_b$0$d = shader$b;
        s_a$0$d = shader$a;
        s_v$0$d = shader$valid;
        s_r$1$d = s_r$0$q;
        s_g$1$d = s_g$0$q;
        s_b$1$d = s_b$0$q;
        s_a$1$d = s_a$0$q;
        s_v$1$d = s_v$0$q;
        compositor$acc_r = bilinear$out$0;
        compositor$acc_g = 16'(bilinear$out$1);
        compositor$acc_b = 16'(bilinear$out$2);
        compositor$acc_a = 16'(bilinear$out$3);
        compositor$new_r = 32'(s_r$1$q);
        compositor$new_g = s_g$1$q;
        compositor$new_b = s_b$1$q;
        compositor$new_a = s_a$1$q;
        compositor$new_valid = s_v$1$q;
        res = 64'(compositor$out_r) | (64'(compositor$out_g) << 'h10) | (64'(compositor$out_b) << 'h20) | (64'(compositor$out_a) << 'h30);
        ring0$write_address = now - 'h3;
        ring0$write_data = res;
        ring0$write_enable = v_q$3$q;
        ring1$write_address = now - 'h3;
        ring1$write_data = res;
        ring1$write_enable = v_q$3$q;
        ring2$write_address = now - 'h3;
        ring2$write_data = res;
        ring2$write_enable = v_q$3$q;
        ring3$write_address = now - 'h3;
        ring3$write_data = res;
        ring3$write_enable = v_q$3$q;
        ring4$write_address = now - 'h3;
        ring4$write_data = res;
        ring4$write_enable = v_q$3$q;
        ring5$write_address = now - 'h3;
        ring5$write_data = res;
        ring5$write_enable = v_q$3$q;
        ring6$write_address = now - 'h3;
        ring6$write_data = res;
        ring6$write_enable = v_q$3$q;
        ring7$write_address = now - 'h3;
        ring7$write_data = res;
        ring7$write_enable = v_q$3$q;
        ring8$write_address = now - 'h3;
        ring8$write_data = res;
        ring8$write_enable = v_q$3$q;
        res_beat = v_q$3$q;
        res_valid = v_q$3$q & ~pad_q$3$q;
        px_valid = v_q$3$q & er_q$3$q & ~pad_q$3$q;
        px_x = bx_q$3$q;
        px_y = by_q$3$q;
        px_face = face_q$3$q;
    end
    
endmodule // top$lanes$2
module top$lanes$2$bx_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$2$bx_q$0
module top$lanes$2$bx_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$2$bx_q$1
module top$lanes$2$bx_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$2$bx_q$2
module top$lanes$2$bx_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$2$bx_q$3
module top$lanes$2$by_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$2$by_q$0
module top$lanes$2$by_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$2$by_q$1
module top$lanes$2$by_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$2$by_q$2
module top$lanes$2$by_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$2$by_q$3
module top$lanes$2$dxm_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$dxm_q
module top$lanes$2$dxn_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$dxn_q
module top$lanes$2$dym_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$dym_q
module top$lanes$2$dyn_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$dyn_q
module top$lanes$2$er_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$2$er_q$0
module top$lanes$2$er_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$2$er_q$1
module top$lanes$2$er_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$2$er_q$2
module top$lanes$2$er_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$2$er_q$3
module top$lanes$2$f0_1(d,q,clock);
    
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
          
endmodule // top$lanes$2$f0_1
module top$lanes$2$f1_1(d,q,clock);
    
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
          
endmodule // top$lanes$2$f1_1
module top$lanes$2$f1_2(d,q,clock);
    
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
          
endmodule // top$lanes$2$f1_2
module top$lanes$2$f3_1(d,q,clock);
    
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
          
endmodule // top$lanes$2$f3_1
module top$lanes$2$f3_2(d,q,clock);
    
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
          
endmodule // top$lanes$2$f3_2
module top$lanes$2$f5_1(d,q,clock);
    
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
          
endmodule // top$lanes$2$f5_1
module top$lanes$2$f5_2(d,q,clock);
    
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
          
endmodule // top$lanes$2$f5_2
module top$lanes$2$f5_3(d,q,clock);
    
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
          
endmodule // top$lanes$2$f5_3
module top$lanes$2$f6_1(d,q,clock);
    
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
          
endmodule // top$lanes$2$f6_1
module top$lanes$2$f7_1(d,q,clock);
    
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
          
endmodule // top$lanes$2$f7_1
module top$lanes$2$f8_1(d,q,clock);
    
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
          
endmodule // top$lanes$2$f8_1
module top$lanes$2$f8l(d,q,clock);
    
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
          
endmodule // top$lanes$2$f8l
module top$lanes$2$face_q$0(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$face_q$0
module top$lanes$2$face_q$1(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$face_q$1
module top$lanes$2$face_q$2(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$face_q$2
module top$lanes$2$face_q$3(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$face_q$3
module top$lanes$2$pad_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$2$pad_q$0
module top$lanes$2$pad_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$2$pad_q$1
module top$lanes$2$pad_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$2$pad_q$2
module top$lanes$2$pad_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$2$pad_q$3
module top$lanes$2$prev0(d,q,clock);
    
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
          
endmodule // top$lanes$2$prev0
module top$lanes$2$prev1(d,q,clock);
    
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
          
endmodule // top$lanes$2$prev1
module top$lanes$2$prev2(d,q,clock);
    
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
          
endmodule // top$lanes$2$prev2
module top$lanes$2$prev3(d,q,clock);
    
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
          
endmodule // top$lanes$2$prev3
module top$lanes$2$prev4(d,q,clock);
    
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
          
endmodule // top$lanes$2$prev4
module top$lanes$2$prev5(d,q,clock);
    
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
          
endmodule // top$lanes$2$prev5
module top$lanes$2$prev6(d,q,clock);
    
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
          
endmodule // top$lanes$2$prev6
module top$lanes$2$prev7(d,q,clock);
    
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
          
endmodule // top$lanes$2$prev7
module top$lanes$2$prev8(d,q,clock);
    
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
          
endmodule // top$lanes$2$prev8
module top$lanes$2$ring0(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[2047:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[10:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[10:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$2$ring0
module top$lanes$2$ring1(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[1:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[0:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[0:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$2$ring1
module top$lanes$2$ring2(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[2047:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[10:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[10:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$2$ring2
module top$lanes$2$ring3(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[2047:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[10:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[10:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$2$ring3
module top$lanes$2$ring4(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[1:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[0:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[0:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$2$ring4
module top$lanes$2$ring5(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[1:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[0:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[0:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$2$ring5
module top$lanes$2$ring6(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[2047:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[10:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[10:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$2$ring6
module top$lanes$2$ring7(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[1:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[0:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[0:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$2$ring7
module top$lanes$2$ring8(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[1:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[0:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[0:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$2$ring8
module top$lanes$2$s_a$0(d,q,clock);
    
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
          
endmodule // top$lanes$2$s_a$0
module top$lanes$2$s_a$1(d,q,clock);
    
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
          
endmodule // top$lanes$2$s_a$1
module top$lanes$2$s_b$0(d,q,clock);
    
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
          
endmodule // top$lanes$2$s_b$0
module top$lanes$2$s_b$1(d,q,clock);
    
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
          
endmodule // top$lanes$2$s_b$1
module top$lanes$2$s_g$0(d,q,clock);
    
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
          
endmodule // top$lanes$2$s_g$0
module top$lanes$2$s_g$1(d,q,clock);
    
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
          
endmodule // top$lanes$2$s_g$1
module top$lanes$2$s_r$0(d,q,clock);
    
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
          
endmodule // top$lanes$2$s_r$0
module top$lanes$2$s_r$1(d,q,clock);
    
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
          
endmodule // top$lanes$2$s_r$1
module top$lanes$2$s_v$0(d,q,clock);
    
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
          
endmodule // top$lanes$2$s_v$0
module top$lanes$2$s_v$1(d,q,clock);
    
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
          
endmodule // top$lanes$2$s_v$1
module top$lanes$2$sr_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$sr_q
module top$lanes$2$v_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$2$v_q$0
module top$lanes$2$v_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$2$v_q$1
module top$lanes$2$v_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$2$v_q$2
module top$lanes$2$v_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$2$v_q$3
module top$lanes$2$x_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$x_q
module top$lanes$2$y_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$y_q
module top$lanes$3(clock,now,beat_valid,value,x,y,pad,invalid,halo,sr,er,base_x,base_y,face,at_edge,dx_neg,dx_mag,dy_neg,dy_mag,g_from_left_xm,g_from_left_ym,g_from_left_zm,g_from_right_xp,g_from_right_yp,g_from_right_zp,g_to_right_xm,g_to_right_ym,g_to_right_zm,g_to_left_xp,g_to_left_yp,g_to_left_zp,t0s0,t0i1,t1s0,t1s1,t1i1,t1i2,t3s0,t3s1,t3i1,t3i2,t5s0,t5s1,t5s2,t5i1,t5i2,t5i3,t6s0,t6i1,t7s0,t7i1,t8s0,t8i1,t8il,res_beat,res_valid,res,px_valid,px_x,px_y,px_face);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] now;
    input wire  beat_valid;
    input wire  [15:0] value;
    input wire  [15:0] x;
    input wire  [15:0] y;
    input wire  pad;
    input wire  invalid;
    input wire  halo;
    input wire  sr;
    input wire  er;
    input wire  [15:0] base_x;
    input wire  [15:0] base_y;
    input wire  [2:0] face;
    input wire  at_edge;
    input wire  dx_neg;
    input wire  [15:0] dx_mag;
    input wire  dy_neg;
    input wire  [15:0] dy_mag;
    input wire  [15:0] g_from_left_xm;
    input wire  [15:0] g_from_left_ym;
    input wire  [15:0] g_from_left_zm;
    input wire  [15:0] g_from_right_xp;
    input wire  [15:0] g_from_right_yp;
    input wire  [15:0] g_from_right_zp;
    output reg  [15:0] g_to_right_xm;
    output reg  [15:0] g_to_right_ym;
    output reg  [15:0] g_to_right_zm;
    output reg  [15:0] g_to_left_xp;
    output reg  [15:0] g_to_left_yp;
    output reg  [15:0] g_to_left_zp;
    output reg  [63:0] t0s0;
    input wire  [63:0] t0i1;
    output reg  [63:0] t1s0;
    output reg  [63:0] t1s1;
    input wire  [63:0] t1i1;
    input wire  [63:0] t1i2;
    output reg  [63:0] t3s0;
    output reg  [63:0] t3s1;
    input wire  [63:0] t3i1;
    input wire  [63:0] t3i2;
    output reg  [63:0] t5s0;
    output reg  [63:0] t5s1;
    output reg  [63:0] t5s2;
    input wire  [63:0] t5i1;
    input wire  [63:0] t5i2;
    input wire  [63:0] t5i3;
    output reg  [63:0] t6s0;
    input wire  [63:0] t6i1;
    output reg  [63:0] t7s0;
    input wire  [63:0] t7i1;
    output reg  [63:0] t8s0;
    input wire  [63:0] t8i1;
    input wire  [63:0] t8il;
    output reg  res_beat;
    output reg  res_valid;
    output reg  [63:0] res;
    output reg  px_valid;
    output reg  [15:0] px_x;
    output reg  [15:0] px_y;
    output reg  [2:0] px_face;
    
    // Constant declarations
    localparam  use_gradient = 1'b0;
    localparam  hops0 = 2'b1;
    localparam  off0 = 16'hfc02;
    localparam  hops1 = 2'b10;
    localparam  off1 = 16'hfc03;
    localparam  off2 = 16'hfc02;
    localparam  hops3 = 2'b10;
    localparam  off3 = 16'hfbf3;
    localparam  off4 = 16'hfc11;
    localparam  hops5 = 2'b11;
    localparam  off5 = 16'hfbf4;
    localparam  hops6 = 2'b1;
    localparam  off6 = 16'hfbf3;
    localparam  hops7 = 2'b1;
    localparam  off7 = 16'hfc12;
    localparam  hops8 = 2'b1;
    localparam  off8 = 16'hfc13;
    localparam  left8 = 1'b1;
    localparam  p_mask = 16'h3;
    localparam  nx_last = 16'h3f;
    localparam  ny_last = 16'h3f;
    localparam  reset = 64'h0;
    localparam  r_mask = 64'hffff;
    localparam  gba_mask = 64'hffff;
    
    // Stub signals
    reg  abc$clock;
    reg  [15:0] abc$now;
    reg  abc$valid;
    reg  [15:0] abc$value;
    reg  [15:0] abc$x;
    reg  [15:0] abc$y;
    reg  abc$pad;
    reg  abc$invalid;
    reg  abc$dx_neg;
    reg  [15:0] abc$dx_mag;
    reg  abc$dy_neg;
    reg  [15:0] abc$dy_mag;
    reg  abc$sr;
    reg  abc$er;
    reg  abc$at_edge;
    reg  [2:0] abc$face;
    reg  [15:0] abc$base_x;
    reg  [15:0] abc$base_y;
    reg  [15:0] abc$from_left_xm;
    reg  [15:0] abc$from_left_ym;
    reg  [15:0] abc$from_left_zm;
    reg  [15:0] abc$from_right_xp;
    reg  [15:0] abc$from_right_yp;
    reg  [15:0] abc$from_right_zp;
    wire  [15:0] abc$to_right_xm = 'h0;
    wire  [15:0] abc$to_right_ym = 'h0;
    wire  [15:0] abc$to_right_zm = 'h0;
    wire  [15:0] abc$to_left_xp = 'h0;
    wire  [15:0] abc$to_left_yp = 'h0;
    wire  [15:0] abc$to_left_zp = 'h0;
    wire  abc$o_valid = 'h0;
    wire  [15:0] abc$o_value = 'h0;
    wire  [15:0] abc$o_x = 'h0;
    wire  [15:0] abc$o_y = 'h0;
    wire  abc$o_pad = 'h0;
    wire  abc$o_invalid = 'h0;
    wire  abc$o_dx_neg = 'h0;
    wire  [15:0] abc$o_dx_mag = 'h0;
    wire  abc$o_dy_neg = 'h0;
    wire  [15:0] abc$o_dy_mag = 'h0;
    wire  abc$o_sr = 'h0;
    wire  abc$o_er = 'h0;
    wire  abc$o_edge = 'h0;
    wire  [2:0] abc$o_face = 'h0;
    wire  [15:0] abc$o_base_x = 'h0;
    wire  [15:0] abc$o_base_y = 'h0;
    wire  abc$gx_neg = 'h0;
    wire  [15:0] abc$gx_mag = 'h0;
    wire  abc$gy_neg = 'h0;
    wire  [15:0] abc$gy_mag = 'h0;
    wire  abc$gz_neg = 'h0;
    wire  [15:0] abc$gz_mag = 'h0;
    reg  shader$clock;
    reg  [15:0] shader$value;
    reg  shader$invalid;
    reg  shader$at_edge;
    reg  shader$gx_neg;
    reg  [15:0] shader$gx_mag;
    reg  shader$gy_neg;
    reg  [15:0] shader$gy_mag;
    reg  shader$gz_neg;
    reg  [15:0] shader$gz_mag;
    wire  [15:0] shader$r;
    wire  [15:0] shader$g;
    wire  [15:0] shader$b;
    wire  [15:0] shader$a;
    wire  shader$valid;
    reg  [15:0] ring0$read_address;
    reg  ring0$read_clock;
    wire  [63:0] ring0$read_data;
    reg  [15:0] ring0$write_address;
    reg  ring0$write_clock;
    reg  [63:0] ring0$write_data;
    reg  ring0$write_enable;
    reg  [63:0] f0_1$d;
    wire  [63:0] f0_1$q;
    reg  f0_1$clock;
    reg  [63:0] prev0$d;
    wire  [63:0] prev0$q;
    reg  prev0$clock;
    reg  [15:0] ring1$read_address;
    reg  ring1$read_clock;
    wire  [63:0] ring1$read_data;
    reg  [15:0] ring1$write_address;
    reg  ring1$write_clock;
    reg  [63:0] ring1$write_data;
    reg  ring1$write_enable;
    reg  [63:0] f1_1$d;
    wire  [63:0] f1_1$q;
    reg  f1_1$clock;
    reg  [63:0] f1_2$d;
    wire  [63:0] f1_2$q;
    reg  f1_2$clock;
    reg  [63:0] prev1$d;
    wire  [63:0] prev1$q;
    reg  prev1$clock;
    reg  [15:0] ring2$read_address;
    reg  ring2$read_clock;
    wire  [63:0] ring2$read_data;
    reg  [15:0] ring2$write_address;
    reg  ring2$write_clock;
    reg  [63:0] ring2$write_data;
    reg  ring2$write_enable;
    reg  [63:0] prev2$d;
    wire  [63:0] prev2$q;
    reg  prev2$clock;
    reg  [15:0] ring3$read_address;
    reg  ring3$read_clock;
    wire  [63:0] ring3$read_data;
    reg  [15:0] ring3$write_address;
    reg  ring3$write_clock;
    reg  [63:0] ring3$write_data;
    reg  ring3$write_enable;
    reg  [63:0] f3_1$d;
    wire  [63:0] f3_1$q;
    reg  f3_1$clock;
    reg  [63:0] f3_2$d;
    wire  [63:0] f3_2$q;
    reg  f3_2$clock;
    reg  [63:0] prev3$d;
    wire  [63:0] prev3$q;
    reg  prev3$clock;
    reg  [15:0] ring4$read_address;
    reg  ring4$read_clock;
    wire  [63:0] ring4$read_data;
    reg  [15:0] ring4$write_address;
    reg  ring4$write_clock;
    reg  [63:0] ring4$write_data;
    reg  ring4$write_enable;
    reg  [63:0] prev4$d;
    wire  [63:0] prev4$q;
    reg  prev4$clock;
    reg  [15:0] ring5$read_address;
    reg  ring5$read_clock;
    wire  [63:0] ring5$read_data;
    reg  [15:0] ring5$write_address;
    reg  ring5$write_clock;
    reg  [63:0] ring5$write_data;
    reg  ring5$write_enable;
    reg  [63:0] f5_1$d;
    wire  [63:0] f5_1$q;
    reg  f5_1$clock;
    reg  [63:0] f5_2$d;
    wire  [63:0] f5_2$q;
    reg  f5_2$clock;
    reg  [63:0] f5_3$d;
    wire  [63:0] f5_3$q;
    reg  f5_3$clock;
    reg  [63:0] prev5$d;
    wire  [63:0] prev5$q;
    reg  prev5$clock;
    reg  [15:0] ring6$read_address;
    reg  ring6$read_clock;
    wire  [63:0] ring6$read_data;
    reg  [15:0] ring6$write_address;
    reg  ring6$write_clock;
    reg  [63:0] ring6$write_data;
    reg  ring6$write_enable;
    reg  [63:0] f6_1$d;
    wire  [63:0] f6_1$q;
    reg  f6_1$clock;
    reg  [63:0] prev6$d;
    wire  [63:0] prev6$q;
    reg  prev6$clock;
    reg  [15:0] ring7$read_address;
    reg  ring7$read_clock;
    wire  [63:0] ring7$read_data;
    reg  [15:0] ring7$write_address;
    reg  ring7$write_clock;
    reg  [63:0] ring7$write_data;
    reg  ring7$write_enable;
    reg  [63:0] f7_1$d;
    wire  [63:0] f7_1$q;
    reg  f7_1$clock;
    reg  [63:0] prev7$d;
    wire  [63:0] prev7$q;
    reg  prev7$clock;
    reg  [15:0] ring8$read_address;
    reg  ring8$read_clock;
    wire  [63:0] ring8$read_data;
    reg  [15:0] ring8$write_address;
    reg  ring8$write_clock;
    reg  [63:0] ring8$write_data;
    reg  ring8$write_enable;
    reg  [63:0] f8_1$d;
    wire  [63:0] f8_1$q;
    reg  f8_1$clock;
    reg  [63:0] prev8$d;
    wire  [63:0] prev8$q;
    reg  prev8$clock;
    reg  [63:0] f8l$d;
    wire  [63:0] f8l$q;
    reg  f8l$clock;
    reg  bilinear$clock;
    reg  [31:0] bilinear$c00$0;
    reg  [31:0] bilinear$c00$1;
    reg  [31:0] bilinear$c00$2;
    reg  [31:0] bilinear$c00$3;
    reg  [31:0] bilinear$c10$0;
    reg  [31:0] bilinear$c10$1;
    reg  [31:0] bilinear$c10$2;
    reg  [31:0] bilinear$c10$3;
    reg  [31:0] bilinear$c01$0;
    reg  [31:0] bilinear$c01$1;
    reg  [31:0] bilinear$c01$2;
    reg  [31:0] bilinear$c01$3;
    reg  [31:0] bilinear$c11$0;
    reg  [31:0] bilinear$c11$1;
    reg  [31:0] bilinear$c11$2;
    reg  [31:0] bilinear$c11$3;
    reg  [15:0] bilinear$wx;
    reg  [15:0] bilinear$wy;
    wire  [31:0] bilinear$out$0;
    wire  [31:0] bilinear$out$1;
    wire  [31:0] bilinear$out$2;
    wire  [31:0] bilinear$out$3;
    reg  compositor$clock;
    reg  [31:0] compositor$acc_r;
    reg  [15:0] compositor$acc_g;
    reg  [15:0] compositor$acc_b;
    reg  [15:0] compositor$acc_a;
    reg  [31:0] compositor$new_r;
    reg  [15:0] compositor$new_g;
    reg  [15:0] compositor$new_b;
    reg  [15:0] compositor$new_a;
    reg  compositor$new_valid;
    wire  [31:0] compositor$out_r;
    wire  [15:0] compositor$out_g;
    wire  [15:0] compositor$out_b;
    wire  [15:0] compositor$out_a;
    reg  v_q$0$d;
    wire  v_q$0$q;
    reg  v_q$0$clock;
    reg  v_q$1$d;
    wire  v_q$1$q;
    reg  v_q$1$clock;
    reg  v_q$2$d;
    wire  v_q$2$q;
    reg  v_q$2$clock;
    reg  v_q$3$d;
    wire  v_q$3$q;
    reg  v_q$3$clock;
    reg  er_q$0$d;
    wire  er_q$0$q;
    reg  er_q$0$clock;
    reg  er_q$1$d;
    wire  er_q$1$q;
    reg  er_q$1$clock;
    reg  er_q$2$d;
    wire  er_q$2$q;
    reg  er_q$2$clock;
    reg  er_q$3$d;
    wire  er_q$3$q;
    reg  er_q$3$clock;
    reg  pad_q$0$d;
    wire  pad_q$0$q;
    reg  pad_q$0$clock;
    reg  pad_q$1$d;
    wire  pad_q$1$q;
    reg  pad_q$1$clock;
    reg  pad_q$2$d;
    wire  pad_q$2$q;
    reg  pad_q$2$clock;
    reg  pad_q$3$d;
    wire  pad_q$3$q;
    reg  pad_q$3$clock;
    reg  [15:0] bx_q$0$d;
    wire  [15:0] bx_q$0$q;
    reg  bx_q$0$clock;
    reg  [15:0] bx_q$1$d;
    wire  [15:0] bx_q$1$q;
    reg  bx_q$1$clock;
    reg  [15:0] bx_q$2$d;
    wire  [15:0] bx_q$2$q;
    reg  bx_q$2$clock;
    reg  [15:0] bx_q$3$d;
    wire  [15:0] bx_q$3$q;
    reg  bx_q$3$clock;
    reg  [15:0] by_q$0$d;
    wire  [15:0] by_q$0$q;
    reg  by_q$0$clock;
    reg  [15:0] by_q$1$d;
    wire  [15:0] by_q$1$q;
    reg  by_q$1$clock;
    reg  [15:0] by_q$2$d;
    wire  [15:0] by_q$2$q;
    reg  by_q$2$clock;
    reg  [15:0] by_q$3$d;
    wire  [15:0] by_q$3$q;
    reg  by_q$3$clock;
    reg  [2:0] face_q$0$d;
    wire  [2:0] face_q$0$q;
    reg  face_q$0$clock;
    reg  [2:0] face_q$1$d;
    wire  [2:0] face_q$1$q;
    reg  face_q$1$clock;
    reg  [2:0] face_q$2$d;
    wire  [2:0] face_q$2$q;
    reg  face_q$2$clock;
    reg  [2:0] face_q$3$d;
    wire  [2:0] face_q$3$q;
    reg  face_q$3$clock;
    reg  [15:0] x_q$d;
    wire  [15:0] x_q$q;
    reg  x_q$clock;
    reg  [15:0] y_q$d;
    wire  [15:0] y_q$q;
    reg  y_q$clock;
    reg  sr_q$d;
    wire  sr_q$q;
    reg  sr_q$clock;
    reg  dxn_q$d;
    wire  dxn_q$q;
    reg  dxn_q$clock;
    reg  [15:0] dxm_q$d;
    wire  [15:0] dxm_q$q;
    reg  dxm_q$clock;
    reg  dyn_q$d;
    wire  dyn_q$q;
    reg  dyn_q$clock;
    reg  [15:0] dym_q$d;
    wire  [15:0] dym_q$q;
    reg  dym_q$clock;
    reg  [15:0] s_r$0$d;
    wire  [15:0] s_r$0$q;
    reg  s_r$0$clock;
    reg  [15:0] s_r$1$d;
    wire  [15:0] s_r$1$q;
    reg  s_r$1$clock;
    reg  [15:0] s_g$0$d;
    wire  [15:0] s_g$0$q;
    reg  s_g$0$clock;
    reg  [15:0] s_g$1$d;
    wire  [15:0] s_g$1$q;
    reg  s_g$1$clock;
    reg  [15:0] s_b$0$d;
    wire  [15:0] s_b$0$q;
    reg  s_b$0$clock;
    reg  [15:0] s_b$1$d;
    wire  [15:0] s_b$1$q;
    reg  s_b$1$clock;
    reg  [15:0] s_a$0$d;
    wire  [15:0] s_a$0$q;
    reg  s_a$0$clock;
    reg  [15:0] s_a$1$d;
    wire  [15:0] s_a$1$q;
    reg  s_a$1$clock;
    reg  s_v$0$d;
    wire  s_v$0$q;
    reg  s_v$0$clock;
    reg  s_v$1$d;
    wire  s_v$1$q;
    reg  s_v$1$clock;
    
    // Local signals
    reg  st_valid;
    reg  [15:0] st_value;
    reg  [15:0] st_x;
    reg  [15:0] st_y;
    reg  st_pad;
    reg  st_invalid;
    reg  st_sr;
    reg  st_er;
    reg  st_edge;
    reg  [2:0] st_face;
    reg  [15:0] st_bx;
    reg  [15:0] st_by;
    reg  st_dxn;
    reg  [15:0] st_dxm;
    reg  st_dyn;
    reg  [15:0] st_dym;
    reg  [63:0] s0;
    reg  [63:0] a0;
    reg  [63:0] s1;
    reg  [63:0] a1;
    reg  [63:0] s2;
    reg  [63:0] a2;
    reg  [63:0] s3;
    reg  [63:0] a3;
    reg  [63:0] s4;
    reg  [63:0] a4;
    reg  [63:0] s5;
    reg  [63:0] a5;
    reg  [63:0] s6;
    reg  [63:0] a6;
    reg  [63:0] s7;
    reg  [63:0] a7;
    reg  [63:0] s8;
    reg  [63:0] a8;
    reg  first;
    reg  last;
    reg  [63:0] c00;
    reg  [63:0] c10;
    reg  [63:0] c01;
    reg  [63:0] c11;
    reg  x_out;
    reg  y_out;
    
    // Sub module instances
    top$lanes$3$shader shader(
        .clock(shader$clock),
        .value(shader$value),
        .invalid(shader$invalid),
        .at_edge(shader$at_edge),
        .gx_neg(shader$gx_neg),
        .gx_mag(shader$gx_mag),
        .gy_neg(shader$gy_neg),
        .gy_mag(shader$gy_mag),
        .gz_neg(shader$gz_neg),
        .gz_mag(shader$gz_mag),
        .r(shader$r),
        .g(shader$g),
        .b(shader$b),
        .a(shader$a),
        .valid(shader$valid)
    );
    top$lanes$3$ring0 ring0(
        .read_address(ring0$read_address),
        .read_clock(ring0$read_clock),
        .read_data(ring0$read_data),
        .write_address(ring0$write_address),
        .write_clock(ring0$write_clock),
        .write_data(ring0$write_data),
        .write_enable(ring0$write_enable)
    );
    top$lanes$3$f0_1 f0_1(
        .d(f0_1$d),
        .q(f0_1$q),
        .clock(f0_1$clock)
    );
    top$lanes$3$prev0 prev0(
        .d(prev0$d),
        .q(prev0$q),
        .clock(prev0$clock)
    );
    top$lanes$3$ring1 ring1(
        .read_address(ring1$read_address),
        .read_clock(ring1$read_clock),
        .read_data(ring1$read_data),
        .write_address(ring1$write_address),
        .write_clock(ring1$write_clock),
        .write_data(ring1$write_data),
        .write_enable(ring1$write_enable)
    );
    top$lanes$3$f1_1 f1_1(
        .d(f1_1$d),
        .q(f1_1$q),
        .clock(f1_1$clock)
    );
    top$lanes$3$f1_2 f1_2(
        .d(f1_2$d),
        .q(f1_2$q),
        .clock(f1_2$clock)
    );
    top$lanes$3$prev1 prev1(
        .d(prev1$d),
        .q(prev1$q),
        .clock(prev1$clock)
    );
    top$lanes$3$ring2 ring2(
        .read_address(ring2$read_address),
        .read_clock(ring2$read_clock),
        .read_data(ring2$read_data),
        .write_address(ring2$write_address),
        .write_clock(ring2$write_clock),
        .write_data(ring2$write_data),
        .write_enable(ring2$write_enable)
    );
    top$lanes$3$prev2 prev2(
        .d(prev2$d),
        .q(prev2$q),
        .clock(prev2$clock)
    );
    top$lanes$3$ring3 ring3(
        .read_address(ring3$read_address),
        .read_clock(ring3$read_clock),
        .read_data(ring3$read_data),
        .write_address(ring3$write_address),
        .write_clock(ring3$write_clock),
        .write_data(ring3$write_data),
        .write_enable(ring3$write_enable)
    );
    top$lanes$3$f3_1 f3_1(
        .d(f3_1$d),
        .q(f3_1$q),
        .clock(f3_1$clock)
    );
    top$lanes$3$f3_2 f3_2(
        .d(f3_2$d),
        .q(f3_2$q),
        .clock(f3_2$clock)
    );
    top$lanes$3$prev3 prev3(
        .d(prev3$d),
        .q(prev3$q),
        .clock(prev3$clock)
    );
    top$lanes$3$ring4 ring4(
        .read_address(ring4$read_address),
        .read_clock(ring4$read_clock),
        .read_data(ring4$read_data),
        .write_address(ring4$write_address),
        .write_clock(ring4$write_clock),
        .write_data(ring4$write_data),
        .write_enable(ring4$write_enable)
    );
    top$lanes$3$prev4 prev4(
        .d(prev4$d),
        .q(prev4$q),
        .clock(prev4$clock)
    );
    top$lanes$3$ring5 ring5(
        .read_address(ring5$read_address),
        .read_clock(ring5$read_clock),
        .read_data(ring5$read_data),
        .write_address(ring5$write_address),
        .write_clock(ring5$write_clock),
        .write_data(ring5$write_data),
        .write_enable(ring5$write_enable)
    );
    top$lanes$3$f5_1 f5_1(
        .d(f5_1$d),
        .q(f5_1$q),
        .clock(f5_1$clock)
    );
    top$lanes$3$f5_2 f5_2(
        .d(f5_2$d),
        .q(f5_2$q),
        .clock(f5_2$clock)
    );
    top$lanes$3$f5_3 f5_3(
        .d(f5_3$d),
        .q(f5_3$q),
        .clock(f5_3$clock)
    );
    top$lanes$3$prev5 prev5(
        .d(prev5$d),
        .q(prev5$q),
        .clock(prev5$clock)
    );
    top$lanes$3$ring6 ring6(
        .read_address(ring6$read_address),
        .read_clock(ring6$read_clock),
        .read_data(ring6$read_data),
        .write_address(ring6$write_address),
        .write_clock(ring6$write_clock),
        .write_data(ring6$write_data),
        .write_enable(ring6$write_enable)
    );
    top$lanes$3$f6_1 f6_1(
        .d(f6_1$d),
        .q(f6_1$q),
        .clock(f6_1$clock)
    );
    top$lanes$3$prev6 prev6(
        .d(prev6$d),
        .q(prev6$q),
        .clock(prev6$clock)
    );
    top$lanes$3$ring7 ring7(
        .read_address(ring7$read_address),
        .read_clock(ring7$read_clock),
        .read_data(ring7$read_data),
        .write_address(ring7$write_address),
        .write_clock(ring7$write_clock),
        .write_data(ring7$write_data),
        .write_enable(ring7$write_enable)
    );
    top$lanes$3$f7_1 f7_1(
        .d(f7_1$d),
        .q(f7_1$q),
        .clock(f7_1$clock)
    );
    top$lanes$3$prev7 prev7(
        .d(prev7$d),
        .q(prev7$q),
        .clock(prev7$clock)
    );
    top$lanes$3$ring8 ring8(
        .read_address(ring8$read_address),
        .read_clock(ring8$read_clock),
        .read_data(ring8$read_data),
        .write_address(ring8$write_address),
        .write_clock(ring8$write_clock),
        .write_data(ring8$write_data),
        .write_enable(ring8$write_enable)
    );
    top$lanes$3$f8_1 f8_1(
        .d(f8_1$d),
        .q(f8_1$q),
        .clock(f8_1$clock)
    );
    top$lanes$3$prev8 prev8(
        .d(prev8$d),
        .q(prev8$q),
        .clock(prev8$clock)
    );
    top$lanes$3$f8l f8l(
        .d(f8l$d),
        .q(f8l$q),
        .clock(f8l$clock)
    );
    top$lanes$3$bilinear bilinear(
        .clock(bilinear$clock),
        .c00$0(bilinear$c00$0),
        .c00$1(bilinear$c00$1),
        .c00$2(bilinear$c00$2),
        .c00$3(bilinear$c00$3),
        .c10$0(bilinear$c10$0),
        .c10$1(bilinear$c10$1),
        .c10$2(bilinear$c10$2),
        .c10$3(bilinear$c10$3),
        .c01$0(bilinear$c01$0),
        .c01$1(bilinear$c01$1),
        .c01$2(bilinear$c01$2),
        .c01$3(bilinear$c01$3),
        .c11$0(bilinear$c11$0),
        .c11$1(bilinear$c11$1),
        .c11$2(bilinear$c11$2),
        .c11$3(bilinear$c11$3),
        .wx(bilinear$wx),
        .wy(bilinear$wy),
        .out$0(bilinear$out$0),
        .out$1(bilinear$out$1),
        .out$2(bilinear$out$2),
        .out$3(bilinear$out$3)
    );
    top$lanes$3$compositor compositor(
        .clock(compositor$clock),
        .acc_r(compositor$acc_r),
        .acc_g(compositor$acc_g),
        .acc_b(compositor$acc_b),
        .acc_a(compositor$acc_a),
        .new_r(compositor$new_r),
        .new_g(compositor$new_g),
        .new_b(compositor$new_b),
        .new_a(compositor$new_a),
        .new_valid(compositor$new_valid),
        .out_r(compositor$out_r),
        .out_g(compositor$out_g),
        .out_b(compositor$out_b),
        .out_a(compositor$out_a)
    );
    top$lanes$3$v_q$0 v_q$0(
        .d(v_q$0$d),
        .q(v_q$0$q),
        .clock(v_q$0$clock)
    );
    top$lanes$3$v_q$1 v_q$1(
        .d(v_q$1$d),
        .q(v_q$1$q),
        .clock(v_q$1$clock)
    );
    top$lanes$3$v_q$2 v_q$2(
        .d(v_q$2$d),
        .q(v_q$2$q),
        .clock(v_q$2$clock)
    );
    top$lanes$3$v_q$3 v_q$3(
        .d(v_q$3$d),
        .q(v_q$3$q),
        .clock(v_q$3$clock)
    );
    top$lanes$3$er_q$0 er_q$0(
        .d(er_q$0$d),
        .q(er_q$0$q),
        .clock(er_q$0$clock)
    );
    top$lanes$3$er_q$1 er_q$1(
        .d(er_q$1$d),
        .q(er_q$1$q),
        .clock(er_q$1$clock)
    );
    top$lanes$3$er_q$2 er_q$2(
        .d(er_q$2$d),
        .q(er_q$2$q),
        .clock(er_q$2$clock)
    );
    top$lanes$3$er_q$3 er_q$3(
        .d(er_q$3$d),
        .q(er_q$3$q),
        .clock(er_q$3$clock)
    );
    top$lanes$3$pad_q$0 pad_q$0(
        .d(pad_q$0$d),
        .q(pad_q$0$q),
        .clock(pad_q$0$clock)
    );
    top$lanes$3$pad_q$1 pad_q$1(
        .d(pad_q$1$d),
        .q(pad_q$1$q),
        .clock(pad_q$1$clock)
    );
    top$lanes$3$pad_q$2 pad_q$2(
        .d(pad_q$2$d),
        .q(pad_q$2$q),
        .clock(pad_q$2$clock)
    );
    top$lanes$3$pad_q$3 pad_q$3(
        .d(pad_q$3$d),
        .q(pad_q$3$q),
        .clock(pad_q$3$clock)
    );
    top$lanes$3$bx_q$0 bx_q$0(
        .d(bx_q$0$d),
        .q(bx_q$0$q),
        .clock(bx_q$0$clock)
    );
    top$lanes$3$bx_q$1 bx_q$1(
        .d(bx_q$1$d),
        .q(bx_q$1$q),
        .clock(bx_q$1$clock)
    );
    top$lanes$3$bx_q$2 bx_q$2(
        .d(bx_q$2$d),
        .q(bx_q$2$q),
        .clock(bx_q$2$clock)
    );
    top$lanes$3$bx_q$3 bx_q$3(
        .d(bx_q$3$d),
        .q(bx_q$3$q),
        .clock(bx_q$3$clock)
    );
    top$lanes$3$by_q$0 by_q$0(
        .d(by_q$0$d),
        .q(by_q$0$q),
        .clock(by_q$0$clock)
    );
    top$lanes$3$by_q$1 by_q$1(
        .d(by_q$1$d),
        .q(by_q$1$q),
        .clock(by_q$1$clock)
    );
    top$lanes$3$by_q$2 by_q$2(
        .d(by_q$2$d),
        .q(by_q$2$q),
        .clock(by_q$2$clock)
    );
    top$lanes$3$by_q$3 by_q$3(
        .d(by_q$3$d),
        .q(by_q$3$q),
        .clock(by_q$3$clock)
    );
    top$lanes$3$face_q$0 face_q$0(
        .d(face_q$0$d),
        .q(face_q$0$q),
        .clock(face_q$0$clock)
    );
    top$lanes$3$face_q$1 face_q$1(
        .d(face_q$1$d),
        .q(face_q$1$q),
        .clock(face_q$1$clock)
    );
    top$lanes$3$face_q$2 face_q$2(
        .d(face_q$2$d),
        .q(face_q$2$q),
        .clock(face_q$2$clock)
    );
    top$lanes$3$face_q$3 face_q$3(
        .d(face_q$3$d),
        .q(face_q$3$q),
        .clock(face_q$3$clock)
    );
    top$lanes$3$x_q x_q(
        .d(x_q$d),
        .q(x_q$q),
        .clock(x_q$clock)
    );
    top$lanes$3$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    top$lanes$3$sr_q sr_q(
        .d(sr_q$d),
        .q(sr_q$q),
        .clock(sr_q$clock)
    );
    top$lanes$3$dxn_q dxn_q(
        .d(dxn_q$d),
        .q(dxn_q$q),
        .clock(dxn_q$clock)
    );
    top$lanes$3$dxm_q dxm_q(
        .d(dxm_q$d),
        .q(dxm_q$q),
        .clock(dxm_q$clock)
    );
    top$lanes$3$dyn_q dyn_q(
        .d(dyn_q$d),
        .q(dyn_q$q),
        .clock(dyn_q$clock)
    );
    top$lanes$3$dym_q dym_q(
        .d(dym_q$d),
        .q(dym_q$q),
        .clock(dym_q$clock)
    );
    top$lanes$3$s_r$0 s_r$0(
        .d(s_r$0$d),
        .q(s_r$0$q),
        .clock(s_r$0$clock)
    );
    top$lanes$3$s_r$1 s_r$1(
        .d(s_r$1$d),
        .q(s_r$1$q),
        .clock(s_r$1$clock)
    );
    top$lanes$3$s_g$0 s_g$0(
        .d(s_g$0$d),
        .q(s_g$0$q),
        .clock(s_g$0$clock)
    );
    top$lanes$3$s_g$1 s_g$1(
        .d(s_g$1$d),
        .q(s_g$1$q),
        .clock(s_g$1$clock)
    );
    top$lanes$3$s_b$0 s_b$0(
        .d(s_b$0$d),
        .q(s_b$0$q),
        .clock(s_b$0$clock)
    );
    top$lanes$3$s_b$1 s_b$1(
        .d(s_b$1$d),
        .q(s_b$1$q),
        .clock(s_b$1$clock)
    );
    top$lanes$3$s_a$0 s_a$0(
        .d(s_a$0$d),
        .q(s_a$0$q),
        .clock(s_a$0$clock)
    );
    top$lanes$3$s_a$1 s_a$1(
        .d(s_a$1$d),
        .q(s_a$1$q),
        .clock(s_a$1$clock)
    );
    top$lanes$3$s_v$0 s_v$0(
        .d(s_v$0$d),
        .q(s_v$0$q),
        .clock(s_v$0$clock)
    );
    top$lanes$3$s_v$1 s_v$1(
        .d(s_v$1$d),
        .q(s_v$1$q),
        .clock(s_v$1$clock)
    );
    
    // Update code
    always @(*) begin
        x_q$clock = clock;
        y_q$clock = clock;
        sr_q$clock = clock;
        dxn_q$clock = clock;
        dxm_q$clock = clock;
        dyn_q$clock = clock;
        dym_q$clock = clock;
        f0_1$clock = clock;
        prev0$clock = clock;
        f1_1$clock = clock;
        f1_2$clock = clock;
        prev1$clock = clock;
        prev2$clock = clock;
        f3_1$clock = clock;
        f3_2$clock = clock;
        prev3$clock = clock;
        prev4$clock = clock;
        f5_1$clock = clock;
        f5_2$clock = clock;
        f5_3$clock = clock;
        prev5$clock = clock;
        f6_1$clock = clock;
        prev6$clock = clock;
        f7_1$clock = clock;
        prev7$clock = clock;
        f8_1$clock = clock;
        prev8$clock = clock;
        f8l$clock = clock;
        x_q$d = x_q$q;
        y_q$d = y_q$q;
        sr_q$d = sr_q$q;
        dxn_q$d = dxn_q$q;
        dxm_q$d = dxm_q$q;
        dyn_q$d = dyn_q$q;
        dym_q$d = dym_q$q;
        f0_1$d = f0_1$q;
        prev0$d = prev0$q;
        f1_1$d = f1_1$q;
        f1_2$d = f1_2$q;
        prev1$d = prev1$q;
        prev2$d = prev2$q;
        f3_1$d = f3_1$q;
        f3_2$d = f3_2$q;
        prev3$d = prev3$q;
        prev4$d = prev4$q;
        f5_1$d = f5_1$q;
        f5_2$d = f5_2$q;
        f5_3$d = f5_3$q;
        prev5$d = prev5$q;
        f6_1$d = f6_1$q;
        prev6$d = prev6$q;
        f7_1$d = f7_1$q;
        prev7$d = prev7$q;
        f8_1$d = f8_1$q;
        prev8$d = prev8$q;
        f8l$d = f8l$q;
        v_q$0$clock = clock;
        er_q$0$clock = clock;
        pad_q$0$clock = clock;
        bx_q$0$clock = clock;
        by_q$0$clock = clock;
        face_q$0$clock = clock;
        v_q$1$clock = clock;
        er_q$1$clock = clock;
        pad_q$1$clock = clock;
        bx_q$1$clock = clock;
        by_q$1$clock = clock;
        face_q$1$clock = clock;
        v_q$2$clock = clock;
        er_q$2$clock = clock;
        pad_q$2$clock = clock;
        bx_q$2$clock = clock;
        by_q$2$clock = clock;
        face_q$2$clock = clock;
        v_q$3$clock = clock;
        er_q$3$clock = clock;
        pad_q$3$clock = clock;
        bx_q$3$clock = clock;
        by_q$3$clock = clock;
        face_q$3$clock = clock;
        s_r$0$clock = clock;
        s_g$0$clock = clock;
        s_b$0$clock = clock;
        s_a$0$clock = clock;
        s_v$0$clock = clock;
        s_r$1$clock = clock;
        s_g$1$clock = clock;
        s_b$1$clock = clock;
        s_a$1$clock = clock;
        s_v$1$clock = clock;
        shader$clock = clock;
        bilinear$clock = clock;
        compositor$clock = clock;
        abc$clock = clock;
        abc$now = now;
        abc$valid = beat_valid & ~halo;
        abc$value = value;
        abc$x = x;
        abc$y = y;
        abc$pad = pad;
        abc$invalid = invalid;
        abc$sr = sr;
        abc$er = er;
        abc$at_edge = at_edge;
        abc$face = face;
        abc$base_x = base_x;
        abc$base_y = base_y;
        abc$dx_neg = dx_neg;
        abc$dx_mag = dx_mag;
        abc$dy_neg = dy_neg;
        abc$dy_mag = dy_mag;
        abc$from_left_xm = g_from_left_xm;
        abc$from_left_ym = g_from_left_ym;
        abc$from_left_zm = g_from_left_zm;
        abc$from_right_xp = g_from_right_xp;
        abc$from_right_yp = g_from_right_yp;
        abc$from_right_zp = g_from_right_zp;
        g_to_right_xm = abc$to_right_xm;
        g_to_right_ym = abc$to_right_ym;
        g_to_right_zm = abc$to_right_zm;
        g_to_left_xp = abc$to_left_xp;
        g_to_left_yp = abc$to_left_yp;
        g_to_left_zp = abc$to_left_zp;
        if (use_gradient) begin
            st_valid = abc$o_valid;
            st_value = abc$o_value;
            st_x = abc$o_x;
            st_y = abc$o_y;
            st_pad = abc$o_pad;
            st_invalid = abc$o_invalid;
            st_sr = abc$o_sr;
            st_er = abc$o_er;
            st_edge = abc$o_edge;
            st_face = abc$o_face;
            st_bx = abc$o_base_x;
            st_by = abc$o_base_y;
            st_dxn = abc$o_dx_neg;
            st_dxm = abc$o_dx_mag;
            st_dyn = abc$o_dy_neg;
            st_dym = abc$o_dy_mag;
        end
        else begin
            st_valid = beat_valid;
            st_value = value;
            st_x = x;
            st_y = y;
            st_pad = pad;
            st_invalid = invalid;
            st_sr = sr;
            st_er = er;
            st_edge = at_edge;
            st_face = face;
            st_bx = base_x;
            st_by = base_y;
            st_dxn = dx_neg;
            st_dxm = dx_mag;
            st_dyn = dy_neg;
            st_dym = dy_mag;
        end
        shader$value = st_value;
        shader$invalid = st_invalid;
        shader$at_edge = st_edge;
        shader$gx_neg = abc$gx_neg;
        shader$gx_mag = abc$gx_mag;
        shader$gy_neg = abc$gy_neg;
        shader$gy_mag = abc$gy_mag;
        shader$gz_neg = abc$gz_neg;
        shader$gz_mag = abc$gz_mag;
        v_q$0$d = st_valid;
        er_q$0$d = st_er;
        pad_q$0$d = st_pad;
        bx_q$0$d = st_bx;
        by_q$0$d = st_by;
        face_q$0$d = st_face;
        v_q$1$d = v_q$0$q;
        er_q$1$d = er_q$0$q;
        pad_q$1$d = pad_q$0$q;
        bx_q$1$d = bx_q$0$q;
        by_q$1$d = by_q$0$q;
        face_q$1$d = face_q$0$q;
        v_q$2$d = v_q$1$q;
        er_q$2$d = er_q$1$q;
        pad_q$2$d = pad_q$1$q;
        bx_q$2$d = bx_q$1$q;
        by_q$2$d = by_q$1$q;
        face_q$2$d = face_q$1$q;
        v_q$3$d = v_q$2$q;
        er_q$3$d = er_q$2$q;
        pad_q$3$d = pad_q$2$q;
        bx_q$3$d = bx_q$2$q;
        by_q$3$d = by_q$2$q;
        face_q$3$d = face_q$2$q;
        x_q$d = st_x;
        y_q$d = st_y;
        sr_q$d = st_sr;
        dxn_q$d = st_dxn;
        dxm_q$d = st_dxm;
        dyn_q$d = st_dyn;
        dym_q$d = st_dym;
        first = (x_q$q & p_mask) == 'h0;
        last = (x_q$q & p_mask) == p_mask;
        ring0$read_clock = clock;
        ring0$write_clock = clock;
        ring0$read_address = now + off0;
        t0s0 = ring0$read_data;
        f0_1$d = t0i1;
        s0 = ring0$read_data;
        if (hops0 == 'h1) begin
            s0 = f0_1$q;
        end
        prev0$d = s0;
        a0 = s0;
        ring1$read_clock = clock;
        ring1$write_clock = clock;
        ring1$read_address = now + off1;
        t1s0 = ring1$read_data;
        f1_1$d = t1i1;
        f1_2$d = t1i2;
        t1s1 = f1_1$q;
        s1 = ring1$read_data;
        if (hops1 == 'h1) begin
            s1 = f1_1$q;
        end
        if (hops1 == 'h2) begin
            s1 = f1_2$q;
        end
        prev1$d = s1;
        a1 = s1;
        if (first) begin
            a1 = prev1$q;
        end
        ring2$read_clock = clock;
        ring2$write_clock = clock;
        ring2$read_address = now + off2;
        s2 = ring2$read_data;
        prev2$d = s2;
        a2 = prev2$q;
        if (last) begin
            a2 = s2;
        end
        ring3$read_clock = clock;
        ring3$write_clock = clock;
        ring3$read_address = now + off3;
        t3s0 = ring3$read_data;
        f3_1$d = t3i1;
        f3_2$d = t3i2;
        t3s1 = f3_1$q;
        s3 = ring3$read_data;
        if (hops3 == 'h1) begin
            s3 = f3_1$q;
        end
        if (hops3 == 'h2) begin
            s3 = f3_2$q;
        end
        prev3$d = s3;
        a3 = s3;
        ring4$read_clock = clock;
        ring4$write_clock = clock;
        ring4$read_address = now + off4;
        s4 = ring4$read_data;
        prev4$d = s4;
        a4 = s4;
        ring5$read_clock = clock;
        ring5$write_clock = clock;
        ring5$read_address = now + off5;
        t5s0 = ring5$read_data;
        f5_1$d = t5i1;
        f5_2$d = t5i2;
        f5_3$d = t5i3;
        t5s1 = f5_1$q;
        t5s2 = f5_2$q;
        s5 = ring5$read_data;
        if (hops5 == 'h1) begin
            s5 = f5_1$q;
        end
        if (hops5 == 'h2) begin
            s5 = f5_2$q;
        end
        if (hops5 == 'h3) begin
            s5 = f5_3$q;
        end
        prev5$d = s5;
        a5 = s5;
        if (first) begin
            a5 = prev5$q;
        end
        ring6$read_clock = clock;
        ring6$write_clock = clock;
        ring6$read_address = now + off6;
        t6s0 = ring6$read_data;
        f6_1$d = t6i1;
        s6 = ring6$read_data;
        if (hops6 == 'h1) begin
            s6 = f6_1$q;
        end
        prev6$d = s6;
        a6 = prev6$q;
        if (last) begin
            a6 = s6;
        end
        ring7$read_clock = clock;
        ring7$write_clock = clock;
        ring7$read_address = now + off7;
        t7s0 = ring7$read_data;
        f7_1$d = t7i1;
        s7 = ring7$read_data;
        if (hops7 == 'h1) begin
            s7 = f7_1$q;
        end
        prev7$d = s7;
        a7 = s7;
        if (first) begin
            a7 = prev7$q;
        end
        ring8$read_clock = clock;
        ring8$write_clock = clock;
        ring8$read_address = now + off8;
        t8s0 = ring8$read_data;
        f8_1$d = t8i1;
        s8 = ring8$read_data;
        if (hops8 == 'h1) begin
            s8 = f8_1$q;
        end
        f8l$d = t8il;
        if (left8) begin
            s8 = f8l$q;
        end
        prev8$d = s8;
        a8 = prev8$q;
        if (last) begin
            a8 = s8;
        end
        c00 = a0;
        c10 = a0;
        c01 = a0;
        c11 = a0;
        x_out = 1'b0;
        y_out = 1'b0;
        if (dxm_q$q != 'h0) begin
            if (dxn_q$q) begin
                c10 = a2;
                x_out = x_q$q == nx_last;
            end
            else begin
                c10 = a1;
                x_out = x_q$q == 'h0;
            end
        end
        if (dym_q$q != 'h0) begin
            if (dyn_q$q) begin
                c01 = a4;
                y_out = y_q$q == ny_last;
            end
            else begin
                c01 = a3;
                y_out = y_q$q == 'h0;
            end
        end
        c11 = c01;
        if (dxm_q$q != 'h0) begin
            c11 = c10;
            if (dym_q$q != 'h0) begin
                if (dxn_q$q) begin
                    if (dyn_q$q) begin
                        c11 = a8;
                    end
                    else begin
                        c11 = a6;
                    end
                end
                else if (dyn_q$q) begin
                    c11 = a7;
                end
                else begin
                    c11 = a5;
                end
            end
        end
        if (x_out) begin
            c10 = reset;
            c11 = reset;
        end
        if (y_out) begin
            c01 = reset;
            c11 = reset;
        end
        if (sr_q$q) begin
            c00 = reset;
            c10 = reset;
            c01 = reset;
            c11 = reset;
        end
        bilinear$c00$0 = 32'(c00 & r_mask);
        bilinear$c00$1 = 32'((c00 >> 'h10) & gba_mask);
        bilinear$c00$2 = 32'((c00 >> 'h20) & gba_mask);
        bilinear$c00$3 = 32'((c00 >> 'h30) & gba_mask);
        bilinear$c10$0 = 32'(c10 & r_mask);
        bilinear$c10$1 = 32'((c10 >> 'h10) & gba_mask);
        bilinear$c10$2 = 32'((c10 >> 'h20) & gba_mask);
        bilinear$c10$3 = 32'((c10 >> 'h30) & gba_mask);
        bilinear$c01$0 = 32'(c01 & r_mask);
        bilinear$c01$1 = 32'((c01 >> 'h10) & gba_mask);
        bilinear$c01$2 = 32'((c01 >> 'h20) & gba_mask);
        bilinear$c01$3 = 32'((c01 >> 'h30) & gba_mask);
        bilinear$c11$0 = 32'(c11 & r_mask);
        bilinear$c11$1 = 32'((c11 >> 'h10) & gba_mask);
        bilinear$c11$2 = 32'((c11 >> 'h20) & gba_mask);
        bilinear$c11$3 = 32'((c11 >> 'h30) & gba_mask);
        bilinear$wx = dxm_q$q;
        bilinear$wy = dym_q$q;
        s_r$0$d = shader$r;
        s_g$0$d = shader$g;
        s_b$0$d = shader$b;
        s_a$0$d = shader$a;
        s_v$0$d = shader$valid;
        s_r$1$d = s_r$0$q;
        s_g$1$d = s_g$0$q;
        s_b$1$d = s_b$0$q;
        s_a$1$d = s_a$0$q;
        s_v$1$d = s_v$0$q;
        compositor$acc_r = bilinear$out$0;
        compositor$acc_g = 16'(bilinear$out$1);
        compositor$acc_b = 16'(bilinear$out$2);
        compositor$acc_a = 16'(bilinear$out$3);
        compositor$new_r = 32'(s_r$1$q);
        compositor$new_g = s_g$1$q;
        compositor$new_b = s_b$1$q;
        compositor$new_a = s_a$1$q;
        compositor$new_valid = s_v$1$q;
        res = 64'(compositor$out_r) | (64'(compositor$out_g) << 'h10) | (64'(compositor$out_b) << 'h20) | (64'(compositor$out_a) << 'h30);
        ring0$write_address = now - 'h3;
        ring0$write_data = res;
        ring0$write_enable = v_q$3$q;
        ring1$write_address = now - 'h3;
        ring1$write_data = res;
        ring1$write_enable = v_q$3$q;
        ring2$write_address = now - 'h3;
        ring2$write_data = res;
        ring2$write_enable = v_q$3$q;
        ring3$write_address = now - 'h3;
        ring3$write_data = res;
        ring3$write_enable = v_q$3$q;
        ring4$write_address = now - 'h3;
        ring4$write_data = res;
        ring4$write_enable = v_q$3$q;
        ring5$write_address = now - 'h3;
        ring5$write_data = res;
        ring5$write_enable = v_q$3$q;
        ring6$write_address = now - 'h3;
        ring6$write_data = res;
        ring6$write_enable = v_q$3$q;
        ring7$write_address = now - 'h3;
        ring7$write_data = res;
        ring7$write_enable = v_q$3$q;
        ring8$write_address = now - 'h3;
        ring8$write_data = res;
        ring8$write_enable = v_q$3$q;
        res_beat = v_q$3$q;
        res_valid = v_q$3$q & ~pad_q$3$q;
        px_valid = v_q$3$q & er_q$3$q & ~pad_q$3$q;
        px_x = bx_q$3$q;
        px_y = by_q$3$q;
        px_face = face_q$3$q;
    end
    
endmodule // top$lanes$3
module top$lanes$3$bx_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$3$bx_q$0
module top$lanes$3$bx_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$3$bx_q$1
module top$lanes$3$bx_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$3$bx_q$2
module top$lanes$3$bx_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$3$bx_q$3
module top$lanes$3$by_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$3$by_q$0
module top$lanes$3$by_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$3$by_q$1
module top$lanes$3$by_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$3$by_q$2
module top$lanes$3$by_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$3$by_q$3
module top$lanes$3$dxm_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$dxm_q
module top$lanes$3$dxn_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$dxn_q
module top$lanes$3$dym_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$dym_q
module top$lanes$3$dyn_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$dyn_q
module top$lanes$3$er_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$3$er_q$0
module top$lanes$3$er_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$3$er_q$1
module top$lanes$3$er_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$3$er_q$2
module top$lanes$3$er_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$3$er_q$3
module top$lanes$3$f0_1(d,q,clock);
    
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
          
endmodule // top$lanes$3$f0_1
module top$lanes$3$f1_1(d,q,clock);
    
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
          
endmodule // top$lanes$3$f1_1
module top$lanes$3$f1_2(d,q,clock);
    
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
          
endmodule // top$lanes$3$f1_2
module top$lanes$3$f3_1(d,q,clock);
    
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
          
endmodule // top$lanes$3$f3_1
module top$lanes$3$f3_2(d,q,clock);
    
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
          
endmodule // top$lanes$3$f3_2
module top$lanes$3$f5_1(d,q,clock);
    
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
          
endmodule // top$lanes$3$f5_1
module top$lanes$3$f5_2(d,q,clock);
    
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
          
endmodule // top$lanes$3$f5_2
module top$lanes$3$f5_3(d,q,clock);
    
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
          
endmodule // top$lanes$3$f5_3
module top$lanes$3$f6_1(d,q,clock);
    
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
          
endmodule // top$lanes$3$f6_1
module top$lanes$3$f7_1(d,q,clock);
    
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
          
endmodule // top$lanes$3$f7_1
module top$lanes$3$f8_1(d,q,clock);
    
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
          
endmodule // top$lanes$3$f8_1
module top$lanes$3$f8l(d,q,clock);
    
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
          
endmodule // top$lanes$3$f8l
module top$lanes$3$face_q$0(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$face_q$0
module top$lanes$3$face_q$1(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$face_q$1
module top$lanes$3$face_q$2(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$face_q$2
module top$lanes$3$face_q$3(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$face_q$3
module top$lanes$3$pad_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$3$pad_q$0
module top$lanes$3$pad_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$3$pad_q$1
module top$lanes$3$pad_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$3$pad_q$2
module top$lanes$3$pad_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$3$pad_q$3
module top$lanes$3$prev0(d,q,clock);
    
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
          
endmodule // top$lanes$3$prev0
module top$lanes$3$prev1(d,q,clock);
    
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
          
endmodule // top$lanes$3$prev1
module top$lanes$3$prev2(d,q,clock);
    
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
          
endmodule // top$lanes$3$prev2
module top$lanes$3$prev3(d,q,clock);
    
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
          
endmodule // top$lanes$3$prev3
module top$lanes$3$prev4(d,q,clock);
    
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
          
endmodule // top$lanes$3$prev4
module top$lanes$3$prev5(d,q,clock);
    
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
          
endmodule // top$lanes$3$prev5
module top$lanes$3$prev6(d,q,clock);
    
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
          
endmodule // top$lanes$3$prev6
module top$lanes$3$prev7(d,q,clock);
    
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
          
endmodule // top$lanes$3$prev7
module top$lanes$3$prev8(d,q,clock);
    
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
          
endmodule // top$lanes$3$prev8
module top$lanes$3$ring0(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[2047:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[10:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[10:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$3$ring0
module top$lanes$3$ring1(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[1:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[0:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[0:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$3$ring1
module top$lanes$3$ring2(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[2047:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[10:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[10:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$3$ring2
module top$lanes$3$ring3(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[2047:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[10:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[10:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$3$ring3
module top$lanes$3$ring4(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[1:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[0:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[0:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$3$ring4
module top$lanes$3$ring5(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[1:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[0:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[0:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$3$ring5
module top$lanes$3$ring6(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[2047:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[10:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[10:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$3$ring6
module top$lanes$3$ring7(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[1:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[0:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[0:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$3$ring7
module top$lanes$3$ring8(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[1:0];
    
    always @(posedge read_clock) begin
       read_data <= {56'd0, mem[read_address[0:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[0:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$lanes$3$ring8
module top$lanes$3$s_a$0(d,q,clock);
    
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
          
endmodule // top$lanes$3$s_a$0
module top$lanes$3$s_a$1(d,q,clock);
    
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
          
endmodule // top$lanes$3$s_a$1
module top$lanes$3$s_b$0(d,q,clock);
    
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
          
endmodule // top$lanes$3$s_b$0
module top$lanes$3$s_b$1(d,q,clock);
    
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
          
endmodule // top$lanes$3$s_b$1
module top$lanes$3$s_g$0(d,q,clock);
    
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
          
endmodule // top$lanes$3$s_g$0
module top$lanes$3$s_g$1(d,q,clock);
    
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
          
endmodule // top$lanes$3$s_g$1
module top$lanes$3$s_r$0(d,q,clock);
    
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
          
endmodule // top$lanes$3$s_r$0
module top$lanes$3$s_r$1(d,q,clock);
    
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
          
endmodule // top$lanes$3$s_r$1
module top$lanes$3$s_v$0(d,q,clock);
    
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
          
endmodule // top$lanes$3$s_v$0
module top$lanes$3$s_v$1(d,q,clock);
    
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
          
endmodule // top$lanes$3$s_v$1
module top$lanes$3$sr_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$sr_q
module top$lanes$3$v_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$3$v_q$0
module top$lanes$3$v_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$3$v_q$1
module top$lanes$3$v_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$3$v_q$2
module top$lanes$3$v_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$3$v_q$3
module top$lanes$3$x_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$x_q
module top$lanes$3$y_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$y_q
module top$now(d,q,clock);
    
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
          
endmodule // top$now
