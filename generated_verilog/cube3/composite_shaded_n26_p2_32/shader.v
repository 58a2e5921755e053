module top$pipeline$shade$0(clock,host_write,host_address,host_data,value,invalid,at_edge,gx_neg,gx_mag,gy_neg,gy_mag,gz_neg,gz_mag,r,g,b,a,valid);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  [15:0] value;
    input wire  invalid;
    input wire  at_edge;
    input wire  gx_neg;
    input wire  [31:0] gx_mag;
    input wire  gy_neg;
    input wire  [31:0] gy_mag;
    input wire  gz_neg;
    input wire  [31:0] gz_mag;
    output reg  [31:0] r;
    output reg  [15:0] g;
    output reg  [15:0] b;
    output reg  [15:0] a;
    output reg  valid;
    
    // Constant declarations
    localparam  gm_on = 1'b0;
    localparam  scalar = 1'b0;
    localparam  xray = 1'b0;
    localparam  shaded = 1'b1;
    localparam  edge_transparent = 1'b1;
    localparam  shift = 8'h0;
    localparam  m_max = 16'hff;
    localparam  enabled = 1'b1;
    
    // Stub signals
    reg  lut$clock;
    reg  lut$host_write;
    reg  [23:0] lut$host_address;
    reg  [63:0] lut$host_data;
    reg  [11:0] lut$address;
    wire  [63:0] lut$data;
    reg  alpha_gm$clock;
    reg  alpha_gm$host_write;
    reg  [23:0] alpha_gm$host_address;
    reg  [63:0] alpha_gm$host_data;
    reg  [15:0] alpha_gm$address;
    wire  [15:0] alpha_gm$data = 'h0;
    reg  gm_bin$clock;
    reg  gm_bin$host_write;
    reg  [23:0] gm_bin$host_address;
    reg  [63:0] gm_bin$host_data;
    reg  [31:0] gm_bin$mag$0;
    reg  [31:0] gm_bin$mag$1;
    reg  [31:0] gm_bin$mag$2;
    wire  [3:0] gm_bin$bin = 'h0;
    reg  normal$clock;
    reg  normal$neg$0;
    reg  normal$neg$1;
    reg  normal$neg$2;
    reg  [31:0] normal$mag$0;
    reg  [31:0] normal$mag$1;
    reg  [31:0] normal$mag$2;
    wire  normal$q_neg$0;
    wire  normal$q_neg$1;
    wire  normal$q_neg$2;
    wire  [3:0] normal$q_mag$0;
    wire  [3:0] normal$q_mag$1;
    wire  [3:0] normal$q_mag$2;
    reg  lighting$clock;
    reg  lighting$host_write;
    reg  [23:0] lighting$host_address;
    reg  [63:0] lighting$host_data;
    reg  lighting$q_neg$0;
    reg  lighting$q_neg$1;
    reg  lighting$q_neg$2;
    reg  [3:0] lighting$q_mag$0;
    reg  [3:0] lighting$q_mag$1;
    reg  [3:0] lighting$q_mag$2;
    wire  [15:0] lighting$diffuse;
    wire  [15:0] lighting$specular;
    reg  neg_in$0$d;
    wire  neg_in$0$q;
    reg  neg_in$0$clock;
    reg  neg_in$1$d;
    wire  neg_in$1$q;
    reg  neg_in$1$clock;
    reg  neg_in$2$d;
    wire  neg_in$2$q;
    reg  neg_in$2$clock;
    reg  [31:0] mag_in$0$d;
    wire  [31:0] mag_in$0$q;
    reg  mag_in$0$clock;
    reg  [31:0] mag_in$1$d;
    wire  [31:0] mag_in$1$q;
    reg  mag_in$1$clock;
    reg  [31:0] mag_in$2$d;
    wire  [31:0] mag_in$2$q;
    reg  mag_in$2$clock;
    reg  [11:0] row_q$0$d;
    wire  [11:0] row_q$0$q;
    reg  row_q$0$clock;
    reg  [11:0] row_q$1$d;
    wire  [11:0] row_q$1$q;
    reg  row_q$1$clock;
    reg  [11:0] row_q$2$d;
    wire  [11:0] row_q$2$q;
    reg  row_q$2$clock;
    reg  [11:0] row_q$3$d;
    wire  [11:0] row_q$3$q;
    reg  row_q$3$clock;
    reg  [63:0] lut_q$0$d;
    wire  [63:0] lut_q$0$q;
    reg  lut_q$0$clock;
    reg  [63:0] lut_q$1$d;
    wire  [63:0] lut_q$1$q;
    reg  lut_q$1$clock;
    reg  [63:0] lut_q$2$d;
    wire  [63:0] lut_q$2$q;
    reg  lut_q$2$clock;
    reg  [63:0] lut_q$3$d;
    wire  [63:0] lut_q$3$q;
    reg  lut_q$3$clock;
    reg  [63:0] lut_q$4$d;
    wire  [63:0] lut_q$4$q;
    reg  lut_q$4$clock;
    reg  [63:0] lut_q$5$d;
    wire  [63:0] lut_q$5$q;
    reg  lut_q$5$clock;
    reg  [63:0] lut_q$6$d;
    wire  [63:0] lut_q$6$q;
    reg  lut_q$6$clock;
    reg  [63:0] lut_q$7$d;
    wire  [63:0] lut_q$7$q;
    reg  lut_q$7$clock;
    reg  [63:0] lut_q$8$d;
    wire  [63:0] lut_q$8$q;
    reg  lut_q$8$clock;
    reg  gate_q$0$d;
    wire  gate_q$0$q;
    reg  gate_q$0$clock;
    reg  gate_q$1$d;
    wire  gate_q$1$q;
    reg  gate_q$1$clock;
    reg  gate_q$2$d;
    wire  gate_q$2$q;
    reg  gate_q$2$clock;
    reg  gate_q$3$d;
    wire  gate_q$3$q;
    reg  gate_q$3$clock;
    reg  gate_q$4$d;
    wire  gate_q$4$q;
    reg  gate_q$4$clock;
    reg  [15:0] alpha_q$0$d;
    wire  [15:0] alpha_q$0$q;
    reg  alpha_q$0$clock;
    reg  [15:0] alpha_q$1$d;
    wire  [15:0] alpha_q$1$q;
    reg  alpha_q$1$clock;
    reg  [15:0] alpha_q$2$d;
    wire  [15:0] alpha_q$2$q;
    reg  alpha_q$2$clock;
    reg  [15:0] alpha_q$3$d;
    wire  [15:0] alpha_q$3$q;
    reg  alpha_q$3$clock;
    reg  [15:0] alpha_q$4$d;
    wire  [15:0] alpha_q$4$q;
    reg  alpha_q$4$clock;
    reg  [15:0] alpha_q$5$d;
    wire  [15:0] alpha_q$5$q;
    reg  alpha_q$5$clock;
    reg  [15:0] alpha_q$6$d;
    wire  [15:0] alpha_q$6$q;
    reg  alpha_q$6$clock;
    reg  [15:0] alpha_q$7$d;
    wire  [15:0] alpha_q$7$q;
    reg  alpha_q$7$clock;
    reg  [15:0] alpha_q$8$d;
    wire  [15:0] alpha_q$8$q;
    reg  alpha_q$8$clock;
    reg  [15:0] value_q$0$d;
    wire  [15:0] value_q$0$q;
    reg  value_q$0$clock;
    reg  [15:0] value_q$1$d;
    wire  [15:0] value_q$1$q;
    reg  value_q$1$clock;
    reg  [15:0] value_q$2$d;
    wire  [15:0] value_q$2$q;
    reg  value_q$2$clock;
    reg  [15:0] value_q$3$d;
    wire  [15:0] value_q$3$q;
    reg  value_q$3$clock;
    reg  [15:0] value_q$4$d;
    wire  [15:0] value_q$4$q;
    reg  value_q$4$clock;
    reg  [15:0] value_q$5$d;
    wire  [15:0] value_q$5$q;
    reg  value_q$5$clock;
    reg  [15:0] value_q$6$d;
    wire  [15:0] value_q$6$q;
    reg  value_q$6$clock;
    reg  [15:0] value_q$7$d;
    wire  [15:0] value_q$7$q;
    reg  value_q$7$clock;
    reg  [15:0] value_q$8$d;
    wire  [15:0] value_q$8$q;
    reg  value_q$8$clock;
    reg  [15:0] value_q$9$d;
    wire  [15:0] value_q$9$q;
    reg  value_q$9$clock;
    reg  [15:0] value_q$10$d;
    wire  [15:0] value_q$10$q;
    reg  value_q$10$clock;
    reg  [15:0] value_q$11$d;
    wire  [15:0] value_q$11$q;
    reg  value_q$11$clock;
    reg  [15:0] value_q$12$d;
    wire  [15:0] value_q$12$q;
    reg  value_q$12$clock;
    reg  [15:0] value_q$13$d;
    wire  [15:0] value_q$13$q;
    reg  value_q$13$clock;
    reg  valid_q$0$d;
    wire  valid_q$0$q;
    reg  valid_q$0$clock;
    reg  valid_q$1$d;
    wire  valid_q$1$q;
    reg  valid_q$1$clock;
    reg  valid_q$2$d;
    wire  valid_q$2$q;
    reg  valid_q$2$clock;
    reg  valid_q$3$d;
    wire  valid_q$3$q;
    reg  valid_q$3$clock;
    reg  valid_q$4$d;
    wire  valid_q$4$q;
    reg  valid_q$4$clock;
    reg  valid_q$5$d;
    wire  valid_q$5$q;
    reg  valid_q$5$clock;
    reg  valid_q$6$d;
    wire  valid_q$6$q;
    reg  valid_q$6$clock;
    reg  valid_q$7$d;
    wire  valid_q$7$q;
    reg  valid_q$7$clock;
    reg  valid_q$8$d;
    wire  valid_q$8$q;
    reg  valid_q$8$clock;
    reg  valid_q$9$d;
    wire  valid_q$9$q;
    reg  valid_q$9$clock;
    reg  valid_q$10$d;
    wire  valid_q$10$q;
    reg  valid_q$10$clock;
    reg  valid_q$11$d;
    wire  valid_q$11$q;
    reg  valid_q$11$clock;
    reg  valid_q$12$d;
    wire  valid_q$12$q;
    reg  valid_q$12$clock;
    reg  valid_q$13$d;
    wire  valid_q$13$q;
    reg  valid_q$13$clock;
    reg  valid_q$14$d;
    wire  valid_q$14$q;
    reg  valid_q$14$clock;
    reg  [15:0] specular_q$d;
    wire  [15:0] specular_q$q;
    reg  specular_q$clock;
    reg  lit_r$clock;
    reg  [15:0] lit_r$a;
    reg  [15:0] lit_r$b;
    wire  [15:0] lit_r$y;
    reg  lit_g$clock;
    reg  [15:0] lit_g$a;
    reg  [15:0] lit_g$b;
    wire  [15:0] lit_g$y;
    reg  lit_b$clock;
    reg  [15:0] lit_b$a;
    reg  [15:0] lit_b$b;
    wire  [15:0] lit_b$y;
    reg  [15:0] shaded_q$0$d;
    wire  [15:0] shaded_q$0$q;
    reg  shaded_q$0$clock;
    reg  [15:0] shaded_q$1$d;
    wire  [15:0] shaded_q$1$q;
    reg  shaded_q$1$clock;
    reg  [15:0] shaded_q$2$d;
    wire  [15:0] shaded_q$2$q;
    reg  shaded_q$2$clock;
    reg  mul_r$clock;
    reg  [15:0] mul_r$a;
    reg  [15:0] mul_r$b;
    wire  [15:0] mul_r$y;
    reg  mul_g$clock;
    reg  [15:0] mul_g$a;
    reg  [15:0] mul_g$b;
    wire  [15:0] mul_g$y;
    reg  mul_b$clock;
    reg  [15:0] mul_b$a;
    reg  [15:0] mul_b$b;
    wire  [15:0] mul_b$y;
    reg  [15:0] r_q$d;
    wire  [15:0] r_q$q;
    reg  r_q$clock;
    reg  [15:0] g_q$d;
    wire  [15:0] g_q$q;
    reg  g_q$clock;
    reg  [15:0] b_q$d;
    wire  [15:0] b_q$q;
    reg  b_q$clock;
    reg  [15:0] a_q$d;
    wire  [15:0] a_q$q;
    reg  a_q$clock;
    
    // Local signals
    reg  [11:0] row;
    reg  gate;
    reg  [31:0] mag$0;
    reg  [31:0] mag$1;
    reg  [31:0] mag$2;
    reg  [15:0] alpha;
    reg  [15:0] diffuse;
    reg  [15:0] specular;
    reg  [31:0] sum_r;
    reg  [31:0] sum_g;
    reg  [31:0] sum_b;
    
    // Sub module instances
    top$pipeline$shade$0$lut lut(
        .clock(lut$clock),
        .host_write(lut$host_write),
        .host_address(lut$host_address),
        .host_data(lut$host_data),
        .address(lut$address),
        .data(lut$data)
    );
    top$pipeline$shade$0$normal normal(
        .clock(normal$clock),
        .neg$0(normal$neg$0),
        .neg$1(normal$neg$1),
        .neg$2(normal$neg$2),
        .mag$0(normal$mag$0),
        .mag$1(normal$mag$1),
        .mag$2(normal$mag$2),
        .q_neg$0(normal$q_neg$0),
        .q_neg$1(normal$q_neg$1),
        .q_neg$2(normal$q_neg$2),
        .q_mag$0(normal$q_mag$0),
        .q_mag$1(normal$q_mag$1),
        .q_mag$2(normal$q_mag$2)
    );
    top$pipeline$shade$0$lighting lighting(
        .clock(lighting$clock),
        .host_write(lighting$host_write),
        .host_address(lighting$host_address),
        .host_data(lighting$host_data),
        .q_neg$0(lighting$q_neg$0),
        .q_neg$1(lighting$q_neg$1),
        .q_neg$2(lighting$q_neg$2),
        .q_mag$0(lighting$q_mag$0),
        .q_mag$1(lighting$q_mag$1),
        .q_mag$2(lighting$q_mag$2),
        .diffuse(lighting$diffuse),
        .specular(lighting$specular)
    );
    top$pipeline$shade$0$neg_in$0 neg_in$0(
        .d(neg_in$0$d),
        .q(neg_in$0$q),
        .clock(neg_in$0$clock)
    );
    top$pipeline$shade$0$neg_in$1 neg_in$1(
        .d(neg_in$1$d),
        .q(neg_in$1$q),
        .clock(neg_in$1$clock)
    );
    top$pipeline$shade$0$neg_in$2 neg_in$2(
        .d(neg_in$2$d),
        .q(neg_in$2$q),
        .clock(neg_in$2$clock)
    );
    top$pipeline$shade$0$mag_in$0 mag_in$0(
        .d(mag_in$0$d),
        .q(mag_in$0$q),
        .clock(mag_in$0$clock)
    );
    top$pipeline$shade$0$mag_in$1 mag_in$1(
        .d(mag_in$1$d),
        .q(mag_in$1$q),
        .clock(mag_in$1$clock)
    );
    top$pipeline$shade$0$mag_in$2 mag_in$2(
        .d(mag_in$2$d),
        .q(mag_in$2$q),
        .clock(mag_in$2$clock)
    );
    top$pipeline$shade$0$row_q$0 row_q$0(
        .d(row_q$0$d),
        .q(row_q$0$q),
        .clock(row_q$0$clock)
    );
    top$pipeline$shade$0$row_q$1 row_q$1(
        .d(row_q$1$d),
        .q(row_q$1$q),
        .clock(row_q$1$clock)
    );
    top$pipeline$shade$0$row_q$2 row_q$2(
        .d(row_q$2$d),
        .q(row_q$2$q),
        .clock(row_q$2$clock)
    );
    top$pipeline$shade$0$row_q$3 row_q$3(
        .d(row_q$3$d),
        .q(row_q$3$q),
        .clock(row_q$3$clock)
    );
    top$pipeline$shade$0$lut_q$0 lut_q$0(
        .d(lut_q$0$d),
        .q(lut_q$0$q),
        .clock(lut_q$0$clock)
    );
    top$pipeline$shade$0$lut_q$1 lut_q$1(
        .d(lut_q$1$d),
        .q(lut_q$1$q),
        .clock(lut_q$1$clock)
    );
    top$pipeline$shade$0$lut_q$2 lut_q$2(
        .d(lut_q$2$d),
        .q(lut_q$2$q),
        .clock(lut_q$2$clock)
    );
    top$pipeline$shade$0$lut_q$3 lut_q$3(
        .d(lut_q$3$d),
        .q(lut_q$3$q),
        .clock(lut_q$3$clock)
    );
    top$pipeline$shade$0$lut_q$4 lut_q$4(
        .d(lut_q$4$d),
        .q(lut_q$4$q),
        .clock(lut_q$4$clock)
    );
    top$pipeline$shade$0$lut_q$5 lut_q$5(
        .d(lut_q$5$d),
        .q(lut_q$5$q),
        .clock(lut_q$5$clock)
    );
    top$pipeline$shade$0$lut_q$6 lut_q$6(
        .d(lut_q$6$d),
        .q(lut_q$6$q),
        .clock(lut_q$6$clock)
    );
    top$pipeline$shade$0$lut_q$7 lut_q$7(
        .d(lut_q$7$d),
        .q(lut_q$7$q),
        .clock(lut_q$7$clock)
    );
    top$pipeline$shade$0$lut_q$8 lut_q$8(
        .d(lut_q$8$d),
        .q(lut_q$8$q),
        .clock(lut_q$8$clock)
    );
    top$pipeline$shade$0$gate_q$0 gate_q$0(
        .d(gate_q$0$d),
        .q(gate_q$0$q),
        .clock(gate_q$0$clock)
    );
    top$pipeline$shade$0$gate_q$1 gate_q$1(
        .d(gate_q$1$d),
        .q(gate_q$1$q),
        .clock(gate_q$1$clock)
    );
    top$pipeline$shade$0$gate_q$2 gate_q$2(
        .d(gate_q$2$d),
        .q(gate_q$2$q),
        .clock(gate_q$2$clock)
    );
    top$pipeline$shade$0$gate_q$3 gate_q$3(
        .d(gate_q$3$d),
        .q(gate_q$3$q),
        .clock(gate_q$3$clock)
    );
    top$pipeline$shade$0$gate_q$4 gate_q$4(
        .d(gate_q$4$d),
        .q(gate_q$4$q),
        .clock(gate_q$4$clock)
    );
    top$pipeline$shade$0$alpha_q$0 alpha_q$0(
        .d(alpha_q$0$d),
        .q(alpha_q$0$q),
        .clock(alpha_q$0$clock)
    );
    top$pipeline$shade$0$alpha_q$1 alpha_q$1(
        .d(alpha_q$1$d),
        .q(alpha_q$1$q),
        .clock(alpha_q$1$clock)
    );
    top$pipeline$shade$0$alpha_q$2 alpha_q$2(
        .d(alpha_q$2$d),
        .q(alpha_q$2$q),
        .clock(alpha_q$2$clock)
    );
    top$pipeline$shade$0$alpha_q$3 alpha_q$3(
        .d(alpha_q$3$d),
        .q(alpha_q$3$q),
        .clock(alpha_q$3$clock)
    );
    top$pipeline$shade$0$alpha_q$4 alpha_q$4(
        .d(alpha_q$4$d),
        .q(alpha_q$4$q),
        .clock(alpha_q$4$clock)
    );
    top$pipeline$shade$0$alpha_q$5 alpha_q$5(
        .d(alpha_q$5$d),
        .q(alpha_q$5$q),
        .clock(alpha_q$5$clock)
    );
    top$pipeline$shade$0$alpha_q$6 alpha_q$6(
        .d(alpha_q$6$d),
        .q(alpha_q$6$q),
        .clock(alpha_q$6$clock)
    );
    top$pipeline$shade$0$alpha_q$7 alpha_q$7(
        .d(alpha_q$7$d),
        .q(alpha_q$7$q),
        .clock(alpha_q$7$clock)
    );
    top$pipeline$shade$0$alpha_q$8 alpha_q$8(
        .d(alpha_q$8$d),
        .q(alpha_q$8$q),
        .clock(alpha_q$8$clock)
    );
    top$pipeline$shade$0$value_q$0 value_q$0(
        .d(value_q$0$d),
        .q(value_q$0$q),
        .clock(value_q$0$clock)
    );
    top$pipeline$shade$0$value_q$1 value_q$1(
        .d(value_q$1$d),
        .q(value_q$1$q),
        .clock(value_q$1$clock)
    );
    top$pipeline$shade$0$value_q$2 value_q$2(
        .d(value_q$2$d),
        .q(value_q$2$q),
        .clock(value_q$2$clock)
    );
    top$pipeline$shade$0$value_q$3 value_q$3(
        .d(value_q$3$d),
        .q(value_q$3$q),
        .clock(value_q$3$clock)
    );
    top$pipeline$shade$0$value_q$4 value_q$4(
        .d(value_q$4$d),
        .q(value_q$4$q),
        .clock(value_q$4$clock)
    );
    top$pipeline$shade$0$value_q$5 value_q$5(
        .d(value_q$5$d),
        .q(value_q$5$q),
        .clock(value_q$5$clock)
    );
    top$pipeline$shade$0$value_q$6 value_q$6(
        .d(value_q$6$d),
        .q(value_q$6$q),
        .clock(value_q$6$clock)
    );
    top$pipeline$shade$0$value_q$7 value_q$7(
        .d(value_q$7$d),
        .q(value_q$7$q),
        .clock(value_q$7$clock)
    );
    top$pipeline$shade$0$value_q$8 value_q$8(
        .d(value_q$8$d),
        .q(value_q$8$q),
        .clock(value_q$8$clock)
    );
    top$pipeline$shade$0$value_q$9 value_q$9(
        .d(value_q$9$d),
        .q(value_q$9$q),
        .clock(value_q$9$clock)
    );
    top$pipeline$shade$0$value_q$10 value_q$10(
        .d(value_q$10$d),
        .q(value_q$10$q),
        .clock(value_q$10$clock)
    );
    top$pipeline$shade$0$value_q$11 value_q$11(
        .d(value_q$11$d),
        .q(value_q$11$q),
        .clock(value_q$11$clock)
    );
    top$pipeline$shade$0$value_q$12 value_q$12(
        .d(value_q$12$d),
        .q(value_q$12$q),
        .clock(value_q$12$clock)
    );
    top$pipeline$shade$0$value_q$13 value_q$13(
        .d(value_q$13$d),
        .q(value_q$13$q),
        .clock(value_q$13$clock)
    );
    top$pipeline$shade$0$valid_q$0 valid_q$0(
        .d(valid_q$0$d),
        .q(valid_q$0$q),
        .clock(valid_q$0$clock)
    );
    top$pipeline$shade$0$valid_q$1 valid_q$1(
        .d(valid_q$1$d),
        .q(valid_q$1$q),
        .clock(valid_q$1$clock)
    );
    top$pipeline$shade$0$valid_q$2 valid_q$2(
        .d(valid_q$2$d),
        .q(valid_q$2$q),
        .clock(valid_q$2$clock)
    );
    top$pipeline$shade$0$valid_q$3 valid_q$3(
        .d(valid_q$3$d),
        .q(valid_q$3$q),
        .clock(valid_q$3$clock)
    );
    top$pipeline$shade$0$valid_q$4 valid_q$4(
        .d(valid_q$4$d),
        .q(valid_q$4$q),
        .clock(valid_q$4$clock)
    );
    top$pipeline$shade$0$valid_q$5 valid_q$5(
        .d(valid_q$5$d),
        .q(valid_q$5$q),
        .clock(valid_q$5$clock)
    );
    top$pipeline$shade$0$valid_q$6 valid_q$6(
        .d(valid_q$6$d),
        .q(valid_q$6$q),
        .clock(valid_q$6$clock)
    );
    top$pipeline$shade$0$valid_q$7 valid_q$7(
        .d(valid_q$7$d),
        .q(valid_q$7$q),
        .clock(valid_q$7$clock)
    );
    top$pipeline$shade$0$valid_q$8 valid_q$8(
        .d(valid_q$8$d),
        .q(valid_q$8$q),
        .clock(valid_q$8$clock)
    );
    top$pipeline$shade$0$valid_q$9 valid_q$9(
        .d(valid_q$9$d),
        .q(valid_q$9$q),
        .clock(valid_q$9$clock)
    );
    top$pipeline$shade$0$valid_q$10 valid_q$10(
        .d(valid_q$10$d),
        .q(valid_q$10$q),
        .clock(valid_q$10$clock)
    );
    top$pipeline$shade$0$valid_q$11 valid_q$11(
        .d(valid_q$11$d),
        .q(valid_q$11$q),
        .clock(valid_q$11$clock)
    );
    top$pipeline$shade$0$valid_q$12 valid_q$12(
        .d(valid_q$12$d),
        .q(valid_q$12$q),
        .clock(valid_q$12$clock)
    );
    top$pipeline$shade$0$valid_q$13 valid_q$13(
        .d(valid_q$13$d),
        .q(valid_q$13$q),
        .clock(valid_q$13$clock)
    );
    top$pipeline$shade$0$valid_q$14 valid_q$14(
        .d(valid_q$14$d),
        .q(valid_q$14$q),
        .clock(valid_q$14$clock)
    );
    top$pipeline$shade$0$specular_q specular_q(
        .d(specular_q$d),
        .q(specular_q$q),
        .clock(specular_q$clock)
    );
    top$pipeline$shade$0$lit_r lit_r(
        .clock(lit_r$clock),
        .a(lit_r$a),
        .b(lit_r$b),
        .y(lit_r$y)
    );
    top$pipeline$shade$0$lit_g lit_g(
        .clock(lit_g$clock),
        .a(lit_g$a),
        .b(lit_g$b),
        .y(lit_g$y)
    );
    top$pipeline$shade$0$lit_b lit_b(
        .clock(lit_b$clock),
        .a(lit_b$a),
        .b(lit_b$b),
        .y(lit_b$y)
    );
    top$pipeline$shade$0$shaded_q$0 shaded_q$0(
        .d(shaded_q$0$d),
        .q(shaded_q$0$q),
        .clock(shaded_q$0$clock)
    );
    top$pipeline$shade$0$shaded_q$1 shaded_q$1(
        .d(shaded_q$1$d),
        .q(shaded_q$1$q),
        .clock(shaded_q$1$clock)
    );
    top$pipeline$shade$0$shaded_q$2 shaded_q$2(
        .d(shaded_q$2$d),
        .q(shaded_q$2$q),
        .clock(shaded_q$2$clock)
    );
    top$pipeline$shade$0$mul_r mul_r(
        .clock(mul_r$clock),
        .a(mul_r$a),
        .b(mul_r$b),
        .y(mul_r$y)
    );
    top$pipeline$shade$0$mul_g mul_g(
        .clock(mul_g$clock),
        .a(mul_g$a),
        .b(mul_g$b),
        .y(mul_g$y)
    );
    top$pipeline$shade$0$mul_b mul_b(
        .clock(mul_b$clock),
        .a(mul_b$a),
        .b(mul_b$b),
        .y(mul_b$y)
    );
    top$pipeline$shade$0$r_q r_q(
        .d(r_q$d),
        .q(r_q$q),
        .clock(r_q$clock)
    );
    top$pipeline$shade$0$g_q g_q(
        .d(g_q$d),
        .q(g_q$q),
        .clock(g_q$clock)
    );
    top$pipeline$shade$0$b_q b_q(
        .d(b_q$d),
        .q(b_q$q),
        .clock(b_q$clock)
    );
    top$pipeline$shade$0$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    
    // Update code
    reg  [31:0] r_pass;
    reg  [15:0] g_pass;
    reg  [15:0] b_pass;
    reg  [15:0] a_pass;
    reg  valid_pass;
    always @(*) begin
        specular_q$clock = clock;
        r_q$clock = clock;
        g_q$clock = clock;
        b_q$clock = clock;
        a_q$clock = clock;
        specular_q$d = specular_q$q;
        r_q$d = r_q$q;
        g_q$d = g_q$q;
        b_q$d = b_q$q;
        a_q$d = a_q$q;
        lut$clock = clock;
        lut$host_write = host_write;
        lut$host_address = host_address;
        lut$host_data = host_data;
        alpha_gm$clock = clock;
        alpha_gm$host_write = host_write;
        alpha_gm$host_address = host_address;
        alpha_gm$host_data = host_data;
        gm_bin$clock = clock;
        gm_bin$host_write = host_write;
        gm_bin$host_address = host_address;
        gm_bin$host_data = host_data;
        lighting$clock = clock;
        lighting$host_write = host_write;
        lighting$host_address = host_address;
        lighting$host_data = host_data;
        normal$clock = clock;
        lit_r$clock = clock;
        lit_g$clock = clock;
        lit_b$clock = clock;
        mul_r$clock = clock;
        mul_g$clock = clock;
        mul_b$clock = clock;
        gate = invalid | (edge_transparent & at_edge);
        row = 12'(value >> shift);
        mag$0 = gx_mag;
        mag$1 = gy_mag;
        mag$2 = gz_mag;
        if (gate) begin
            row = 'h0;
            mag$0 = 'h0;
            mag$1 = 'h0;
            mag$2 = 'h0;
        end
        neg_in$0$clock = clock;
        mag_in$0$clock = clock;
        mag_in$0$d = mag$0;
        neg_in$1$clock = clock;
        mag_in$1$clock = clock;
        mag_in$1$d = mag$1;
        neg_in$2$clock = clock;
        mag_in$2$clock = clock;
        mag_in$2$d = mag$2;
        neg_in$0$d = gx_neg & ~gate;
        neg_in$1$d = gy_neg & ~gate;
        neg_in$2$d = gz_neg & ~gate;
        lut$address = row_q$0$q;
        normal$neg$0 = neg_in$0$q;
        normal$mag$0 = mag_in$0$q;
        gm_bin$mag$0 = mag_in$0$q;
        lighting$q_neg$0 = normal$q_neg$0;
        lighting$q_mag$0 = normal$q_mag$0;
        normal$neg$1 = neg_in$1$q;
        normal$mag$1 = mag_in$1$q;
        gm_bin$mag$1 = mag_in$1$q;
        lighting$q_neg$1 = normal$q_neg$1;
        lighting$q_mag$1 = normal$q_mag$1;
        normal$neg$2 = neg_in$2$q;
        normal$mag$2 = mag_in$2$q;
        gm_bin$mag$2 = mag_in$2$q;
        lighting$q_neg$2 = normal$q_neg$2;
        lighting$q_mag$2 = normal$q_mag$2;
        row_q$0$clock = clock;
        row_q$1$clock = clock;
        row_q$2$clock = clock;
        row_q$3$clock = clock;
        row_q$0$d = row;
        row_q$1$d = row_q$0$q;
        row_q$2$d = row_q$1$q;
        row_q$3$d = row_q$2$q;
        lut_q$0$clock = clock;
        alpha_q$0$clock = clock;
        lut_q$1$clock = clock;
        alpha_q$1$clock = clock;
        lut_q$2$clock = clock;
        alpha_q$2$clock = clock;
        lut_q$3$clock = clock;
        alpha_q$3$clock = clock;
        lut_q$4$clock = clock;
        alpha_q$4$clock = clock;
        lut_q$5$clock = clock;
        alpha_q$5$clock = clock;
        lut_q$6$clock = clock;
        alpha_q$6$clock = clock;
        lut_q$7$clock = clock;
        alpha_q$7$clock = clock;
        lut_q$8$clock = clock;
        alpha_q$8$clock = clock;
        lut_q$0$d = lut$data;
        lut_q$1$d = lut_q$0$q;
        lut_q$2$d = lut_q$1$q;
        lut_q$3$d = lut_q$2$q;
        lut_q$4$d = lut_q$3$q;
        lut_q$5$d = lut_q$4$q;
        lut_q$6$d = lut_q$5$q;
        lut_q$7$d = lut_q$6$q;
        lut_q$8$d = lut_q$7$q;
        gate_q$0$clock = clock;
        gate_q$1$clock = clock;
        gate_q$2$clock = clock;
        gate_q$3$clock = clock;
        gate_q$4$clock = clock;
        gate_q$0$d = gate;
        gate_q$1$d = gate_q$0$q;
        gate_q$2$d = gate_q$1$q;
        gate_q$3$d = gate_q$2$q;
        gate_q$4$d = gate_q$3$q;
        value_q$0$clock = clock;
        value_q$1$clock = clock;
        value_q$2$clock = clock;
        value_q$3$clock = clock;
        value_q$4$clock = clock;
        value_q$5$clock = clock;
        value_q$6$clock = clock;
        value_q$7$clock = clock;
        value_q$8$clock = clock;
        value_q$9$clock = clock;
        value_q$10$clock = clock;
        value_q$11$clock = clock;
        value_q$12$clock = clock;
        value_q$13$clock = clock;
        valid_q$0$clock = clock;
        valid_q$1$clock = clock;
        valid_q$2$clock = clock;
        valid_q$3$clock = clock;
        valid_q$4$clock = clock;
        valid_q$5$clock = clock;
        valid_q$6$clock = clock;
        valid_q$7$clock = clock;
        valid_q$8$clock = clock;
        valid_q$9$clock = clock;
        valid_q$10$clock = clock;
        valid_q$11$clock = clock;
        valid_q$12$clock = clock;
        valid_q$13$clock = clock;
        valid_q$14$clock = clock;
        value_q$0$d = value;
        valid_q$0$d = ~invalid | xray;
        value_q$1$d = value_q$0$q;
        value_q$2$d = value_q$1$q;
        value_q$3$d = value_q$2$q;
        value_q$4$d = value_q$3$q;
        value_q$5$d = value_q$4$q;
        value_q$6$d = value_q$5$q;
        value_q$7$d = value_q$6$q;
        value_q$8$d = value_q$7$q;
        value_q$9$d = value_q$8$q;
        value_q$10$d = value_q$9$q;
        value_q$11$d = value_q$10$q;
        value_q$12$d = value_q$11$q;
        value_q$13$d = value_q$12$q;
        valid_q$1$d = valid_q$0$q;
        valid_q$2$d = valid_q$1$q;
        valid_q$3$d = valid_q$2$q;
        valid_q$4$d = valid_q$3$q;
        valid_q$5$d = valid_q$4$q;
        valid_q$6$d = valid_q$5$q;
        valid_q$7$d = valid_q$6$q;
        valid_q$8$d = valid_q$7$q;
        valid_q$9$d = valid_q$8$q;
        valid_q$10$d = valid_q$9$q;
        valid_q$11$d = valid_q$10$q;
        valid_q$12$d = valid_q$11$q;
        valid_q$13$d = valid_q$12$q;
        valid_q$14$d = valid_q$13$q;
        alpha_gm$address = (16'(row_q$3$q) << 'h4) | 16'(gm_bin$bin);
        alpha = 16'(lut_q$2$q >> 'h30);
        if (gm_on) begin
            alpha = alpha_gm$data;
        end
        if (gate_q$4$q) begin
            alpha = 'h0;
        end
        alpha_q$0$d = alpha;
        alpha_q$1$d = alpha_q$0$q;
        alpha_q$2$d = alpha_q$1$q;
        alpha_q$3$d = alpha_q$2$q;
        alpha_q$4$d = alpha_q$3$q;
        alpha_q$5$d = alpha_q$4$q;
        alpha_q$6$d = alpha_q$5$q;
        alpha_q$7$d = alpha_q$6$q;
        alpha_q$8$d = alpha_q$7$q;
        diffuse = m_max;
        specular = 'h0;
        if (shaded) begin
            diffuse = lighting$diffuse;
            specular = lighting$specular;
        end
        specular_q$d = specular;
        lit_r$a = 16'(lut_q$8$q);
        lit_g$a = 16'(lut_q$8$q >> 'h10);
        lit_b$a = 16'(lut_q$8$q >> 'h20);
        lit_r$b = diffuse;
        lit_g$b = diffuse;
        lit_b$b = diffuse;
        sum_r = 32'(lit_r$y) + 32'(specular_q$q);
        sum_g = 32'(lit_g$y) + 32'(specular_q$q);
        sum_b = 32'(lit_b$y) + 32'(specular_q$q);
        shaded_q$0$clock = clock;
        shaded_q$1$clock = clock;
        shaded_q$2$clock = clock;
        shaded_q$0$d = 16'(sum_r);
        if (sum_r > 32'(m_max)) begin
            shaded_q$0$d = m_max;
        end
        shaded_q$1$d = 16'(sum_g);
        if (sum_g > 32'(m_max)) begin
            shaded_q$1$d = m_max;
        end
        shaded_q$2$d = 16'(sum_b);
        if (sum_b > 32'(m_max)) begin
            shaded_q$2$d = m_max;
        end
        mul_r$a = shaded_q$0$q;
        mul_g$a = shaded_q$1$q;
        mul_b$a = shaded_q$2$q;
        mul_r$b = alpha_q$7$q;
        mul_g$b = alpha_q$7$q;
        mul_b$b = alpha_q$7$q;
        if (scalar) begin
            r_q$d = value_q$13$q;
            g_q$d = 'h0;
            b_q$d = 'h0;
            a_q$d = 'h0;
        end
        else if (xray) begin
            r_q$d = alpha_q$8$q;
            g_q$d = 'h0;
            b_q$d = 'h0;
            a_q$d = 'h0;
        end
        else begin
            r_q$d = mul_r$y;
            g_q$d = mul_g$y;
            b_q$d = mul_b$y;
            a_q$d = alpha_q$8$q;
        end
        r_pass = 'h0;
        g_pass = 'h0;
        b_pass = 'h0;
        a_pass = 'h0;
        valid_pass = 1'b0;
        if (enabled) begin
            r_pass = 32'(r_q$q);
            g_pass = g_q$q;
            b_pass = b_q$q;
            a_pass = a_q$q;
            valid_pass = valid_q$14$q;
        end
        r = r_pass;
        g = g_pass;
        b = b_pass;
        a = a_pass;
        valid = valid_pass;
    end
    
endmodule // top$pipeline$shade$0
module top$pipeline$shade$0$a_q(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$a_q
module top$pipeline$shade$0$alpha_q$0(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$alpha_q$0
module top$pipeline$shade$0$alpha_q$1(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$alpha_q$1
module top$pipeline$shade$0$alpha_q$2(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$alpha_q$2
module top$pipeline$shade$0$alpha_q$3(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$alpha_q$3
module top$pipeline$shade$0$alpha_q$4(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$alpha_q$4
module top$pipeline$shade$0$alpha_q$5(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$alpha_q$5
module top$pipeline$shade$0$alpha_q$6(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$alpha_q$6
module top$pipeline$shade$0$alpha_q$7(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$alpha_q$7
module top$pipeline$shade$0$alpha_q$8(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$alpha_q$8
module top$pipeline$shade$0$b_q(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$b_q
module top$pipeline$shade$0$g_q(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$g_q
module top$pipeline$shade$0$gate_q$0(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$gate_q$0
module top$pipeline$shade$0$gate_q$1(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$gate_q$1
module top$pipeline$shade$0$gate_q$2(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$gate_q$2
module top$pipeline$shade$0$gate_q$3(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$gate_q$3
module top$pipeline$shade$0$gate_q$4(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$gate_q$4
module top$pipeline$shade$0$lighting(clock,host_write,host_address,host_data,q_neg$0,q_neg$1,q_neg$2,q_mag$0,q_mag$1,q_mag$2,diffuse,specular);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  q_neg$0;
    input wire  q_neg$1;
    input wire  q_neg$2;
    input wire  [3:0] q_mag$0;
    input wire  [3:0] q_mag$1;
    input wire  [3:0] q_mag$2;
    output reg  [15:0] diffuse;
    output reg  [15:0] specular;
    
    // Constant declarations
    localparam  half_ulp = 64'h2000000;
    localparam  shift = 8'h1a;
    localparam  last = 64'h3ff;
    
    // Stub signals
    reg  regs$clock;
    reg  regs$host_write;
    reg  [23:0] regs$host_address;
    reg  [63:0] regs$host_data;
    wire  [63:0] regs$q$0;
    wire  [63:0] regs$q$1;
    reg  [9:0] rnorm$address;
    wire  [15:0] rnorm$data;
    reg  [3:0] square$0$address;
    wire  [7:0] square$0$data;
    reg  [3:0] square$1$address;
    wire  [7:0] square$1$data;
    reg  [3:0] square$2$address;
    wire  [7:0] square$2$data;
    reg  diffuse_table$clock;
    reg  diffuse_table$host_write;
    reg  [23:0] diffuse_table$host_address;
    reg  [63:0] diffuse_table$host_data;
    reg  [9:0] diffuse_table$address;
    wire  [15:0] diffuse_table$data;
    reg  specular_table$clock;
    reg  specular_table$host_write;
    reg  [23:0] specular_table$host_address;
    reg  [63:0] specular_table$host_data;
    reg  [9:0] specular_table$address;
    wire  [15:0] specular_table$data;
    reg  [15:0] ml_q$0$d;
    wire  [15:0] ml_q$0$q;
    reg  ml_q$0$clock;
    reg  [15:0] ml_q$1$d;
    wire  [15:0] ml_q$1$q;
    reg  ml_q$1$clock;
    reg  [15:0] ml_q$2$d;
    wire  [15:0] ml_q$2$q;
    reg  ml_q$2$clock;
    reg  [15:0] mh_q$0$d;
    wire  [15:0] mh_q$0$q;
    reg  mh_q$0$clock;
    reg  [15:0] mh_q$1$d;
    wire  [15:0] mh_q$1$q;
    reg  mh_q$1$clock;
    reg  [15:0] mh_q$2$d;
    wire  [15:0] mh_q$2$q;
    reg  mh_q$2$clock;
    reg  [31:0] p_l$0$d;
    wire  [31:0] p_l$0$q;
    reg  p_l$0$clock;
    reg  [31:0] p_l$1$d;
    wire  [31:0] p_l$1$q;
    reg  p_l$1$clock;
    reg  [31:0] p_l$2$d;
    wire  [31:0] p_l$2$q;
    reg  p_l$2$clock;
    reg  [31:0] p_h$0$d;
    wire  [31:0] p_h$0$q;
    reg  p_h$0$clock;
    reg  [31:0] p_h$1$d;
    wire  [31:0] p_h$1$q;
    reg  p_h$1$clock;
    reg  [31:0] p_h$2$d;
    wire  [31:0] p_h$2$q;
    reg  p_h$2$clock;
    reg  sl_q$0$d;
    wire  sl_q$0$q;
    reg  sl_q$0$clock;
    reg  sl_q$1$d;
    wire  sl_q$1$q;
    reg  sl_q$1$clock;
    reg  sl_q$2$d;
    wire  sl_q$2$q;
    reg  sl_q$2$clock;
    reg  sh_q$0$d;
    wire  sh_q$0$q;
    reg  sh_q$0$clock;
    reg  sh_q$1$d;
    wire  sh_q$1$q;
    reg  sh_q$1$clock;
    reg  sh_q$2$d;
    wire  sh_q$2$q;
    reg  sh_q$2$clock;
    reg  [15:0] n2_q$d;
    wire  [15:0] n2_q$q;
    reg  n2_q$clock;
    reg  [31:0] dot_l$d;
    wire  [31:0] dot_l$q;
    reg  dot_l$clock;
    reg  [31:0] dot_h$d;
    wire  [31:0] dot_h$q;
    reg  dot_h$clock;
    reg  [15:0] rn$d;
    wire  [15:0] rn$q;
    reg  rn$clock;
    reg  [15:0] d16_l$d;
    wire  [15:0] d16_l$q;
    reg  d16_l$clock;
    reg  [15:0] d16_h$d;
    wire  [15:0] d16_h$q;
    reg  d16_h$clock;
    reg  [15:0] rn_3$d;
    wire  [15:0] rn_3$q;
    reg  rn_3$clock;
    reg  lit_3$d;
    wire  lit_3$q;
    reg  lit_3$clock;
    reg  [31:0] t_l$d;
    wire  [31:0] t_l$q;
    reg  t_l$clock;
    reg  [31:0] t_h$d;
    wire  [31:0] t_h$q;
    reg  t_h$clock;
    reg  lit_4$d;
    wire  lit_4$q;
    reg  lit_4$clock;
    reg  [9:0] idx_l$d;
    wire  [9:0] idx_l$q;
    reg  idx_l$clock;
    reg  [9:0] idx_h$d;
    wire  [9:0] idx_h$q;
    reg  idx_h$clock;
    reg  lit_5$d;
    wire  lit_5$q;
    reg  lit_5$clock;
    reg  lit_6$d;
    wire  lit_6$q;
    reg  lit_6$clock;
    reg  [15:0] diffuse_q$d;
    wire  [15:0] diffuse_q$q;
    reg  diffuse_q$clock;
    reg  [15:0] specular_q$d;
    wire  [15:0] specular_q$q;
    reg  specular_q$clock;
    
    // Local signals
    reg  [15:0] m_l$0;
    reg  [15:0] m_l$1;
    reg  [15:0] m_l$2;
    reg  [15:0] m_h$0;
    reg  [15:0] m_h$1;
    reg  [15:0] m_h$2;
    reg  [15:0] qm$0;
    reg  [15:0] qm$1;
    reg  [15:0] qm$2;
    reg  [31:0] t_pl$0;
    reg  [31:0] t_pl$1;
    reg  [31:0] t_pl$2;
    reg  [31:0] t_ph$0;
    reg  [31:0] t_ph$1;
    reg  [31:0] t_ph$2;
    reg  [15:0] n2;
    reg  [63:0] i_l;
    reg  [63:0] i_h;
    
    // Sub module instances
    top$pipeline$shade$0$lighting$regs regs(
        .clock(regs$clock),
        .host_write(regs$host_write),
        .host_address(regs$host_address),
        .host_data(regs$host_data),
        .q$0(regs$q$0),
        .q$1(regs$q$1)
    );
    top$pipeline$shade$0$lighting$rnorm rnorm(
        .address(rnorm$address),
        .data(rnorm$data)
    );
    top$pipeline$shade$0$lighting$square$0 square$0(
        .address(square$0$address),
        .data(square$0$data)
    );
    top$pipeline$shade$0$lighting$square$1 square$1(
        .address(square$1$address),
        .data(square$1$data)
    );
    top$pipeline$shade$0$lighting$square$2 square$2(
        .address(square$2$address),
        .data(square$2$data)
    );
    top$pipeline$shade$0$lighting$diffuse_table diffuse_table(
        .clock(diffuse_table$clock),
        .host_write(diffuse_table$host_write),
        .host_address(diffuse_table$host_address),
        .host_data(diffuse_table$host_data),
        .address(diffuse_table$address),
        .data(diffuse_table$data)
    );
    top$pipeline$shade$0$lighting$specular_table specular_table(
        .clock(specular_table$clock),
        .host_write(specular_table$host_write),
        .host_address(specular_table$host_address),
        .host_data(specular_table$host_data),
        .address(specular_table$address),
        .data(specular_table$data)
    );
    top$pipeline$shade$0$lighting$ml_q$0 ml_q$0(
        .d(ml_q$0$d),
        .q(ml_q$0$q),
        .clock(ml_q$0$clock)
    );
    top$pipeline$shade$0$lighting$ml_q$1 ml_q$1(
        .d(ml_q$1$d),
        .q(ml_q$1$q),
        .clock(ml_q$1$clock)
    );
    top$pipeline$shade$0$lighting$ml_q$2 ml_q$2(
        .d(ml_q$2$d),
        .q(ml_q$2$q),
        .clock(ml_q$2$clock)
    );
    top$pipeline$shade$0$lighting$mh_q$0 mh_q$0(
        .d(mh_q$0$d),
        .q(mh_q$0$q),
        .clock(mh_q$0$clock)
    );
    top$pipeline$shade$0$lighting$mh_q$1 mh_q$1(
        .d(mh_q$1$d),
        .q(mh_q$1$q),
        .clock(mh_q$1$clock)
    );
    top$pipeline$shade$0$lighting$mh_q$2 mh_q$2(
        .d(mh_q$2$d),
        .q(mh_q$2$q),
        .clock(mh_q$2$clock)
    );
    top$pipeline$shade$0$lighting$p_l$0 p_l$0(
        .d(p_l$0$d),
        .q(p_l$0$q),
        .clock(p_l$0$clock)
    );
    top$pipeline$shade$0$lighting$p_l$1 p_l$1(
        .d(p_l$1$d),
        .q(p_l$1$q),
        .clock(p_l$1$clock)
    );
    top$pipeline$shade$0$lighting$p_l$2 p_l$2(
        .d(p_l$2$d),
        .q(p_l$2$q),
        .clock(p_l$2$clock)
    );
    top$pipeline$shade$0$lighting$p_h$0 p_h$0(
        .d(p_h$0$d),
        .q(p_h$0$q),
        .clock(p_h$0$clock)
    );
    top$pipeline$shade$0$lighting$p_h$1 p_h$1(
        .d(p_h$1$d),
        .q(p_h$1$q),
        .clock(p_h$1$clock)
    );
    top$pipeline$shade$0$lighting$p_h$2 p_h$2(
        .d(p_h$2$d),
        .q(p_h$2$q),
        .clock(p_h$2$clock)
    );
    top$pipeline$shade$0$lighting$sl_q$0 sl_q$0(
        .d(sl_q$0$d),
        .q(sl_q$0$q),
        .clock(sl_q$0$clock)
    );
    top$pipeline$shade$0$lighting$sl_q$1 sl_q$1(
        .d(sl_q$1$d),
        .q(sl_q$1$q),
        .clock(sl_q$1$clock)
    );
    top$pipeline$shade$0$lighting$sl_q$2 sl_q$2(
        .d(sl_q$2$d),
        .q(sl_q$2$q),
        .clock(sl_q$2$clock)
    );
    top$pipeline$shade$0$lighting$sh_q$0 sh_q$0(
        .d(sh_q$0$d),
        .q(sh_q$0$q),
        .clock(sh_q$0$clock)
    );
    top$pipeline$shade$0$lighting$sh_q$1 sh_q$1(
        .d(sh_q$1$d),
        .q(sh_q$1$q),
        .clock(sh_q$1$clock)
    );
    top$pipeline$shade$0$lighting$sh_q$2 sh_q$2(
        .d(sh_q$2$d),
        .q(sh_q$2$q),
        .clock(sh_q$2$clock)
    );
    top$pipeline$shade$0$lighting$n2_q n2_q(
        .d(n2_q$d),
        .q(n2_q$q),
        .clock(n2_q$clock)
    );
    top$pipeline$shade$0$lighting$dot_l dot_l(
        .d(dot_l$d),
        .q(dot_l$q),
        .clock(dot_l$clock)
    );
    top$pipeline$shade$0$lighting$dot_h dot_h(
        .d(dot_h$d),
        .q(dot_h$q),
        .clock(dot_h$clock)
    );
    top$pipeline$shade$0$lighting$rn rn(
        .d(rn$d),
        .q(rn$q),
        .clock(rn$clock)
    );
    top$pipeline$shade$0$lighting$d16_l d16_l(
        .d(d16_l$d),
        .q(d16_l$q),
        .clock(d16_l$clock)
    );
    top$pipeline$shade$0$lighting$d16_h d16_h(
        .d(d16_h$d),
        .q(d16_h$q),
        .clock(d16_h$clock)
    );
    top$pipeline$shade$0$lighting$rn_3 rn_3(
        .d(rn_3$d),
        .q(rn_3$q),
        .clock(rn_3$clock)
    );
    top$pipeline$shade$0$lighting$lit_3 lit_3(
        .d(lit_3$d),
        .q(lit_3$q),
        .clock(lit_3$clock)
    );
    top$pipeline$shade$0$lighting$t_l t_l(
        .d(t_l$d),
        .q(t_l$q),
        .clock(t_l$clock)
    );
    top$pipeline$shade$0$lighting$t_h t_h(
        .d(t_h$d),
        .q(t_h$q),
        .clock(t_h$clock)
    );
    top$pipeline$shade$0$lighting$lit_4 lit_4(
        .d(lit_4$d),
        .q(lit_4$q),
        .clock(lit_4$clock)
    );
    top$pipeline$shade$0$lighting$idx_l idx_l(
        .d(idx_l$d),
        .q(idx_l$q),
        .clock(idx_l$clock)
    );
    top$pipeline$shade$0$lighting$idx_h idx_h(
        .d(idx_h$d),
        .q(idx_h$q),
        .clock(idx_h$clock)
    );
    top$pipeline$shade$0$lighting$lit_5 lit_5(
        .d(lit_5$d),
        .q(lit_5$q),
        .clock(lit_5$clock)
    );
    top$pipeline$shade$0$lighting$lit_6 lit_6(
        .d(lit_6$d),
        .q(lit_6$q),
        .clock(lit_6$clock)
    );
    top$pipeline$shade$0$lighting$diffuse_q diffuse_q(
        .d(diffuse_q$d),
        .q(diffuse_q$q),
        .clock(diffuse_q$clock)
    );
    top$pipeline$shade$0$lighting$specular_q specular_q(
        .d(specular_q$d),
        .q(specular_q$q),
        .clock(specular_q$clock)
    );
    
    // Update code
    always @(*) begin
        n2_q$clock = clock;
        dot_l$clock = clock;
        dot_h$clock = clock;
        rn$clock = clock;
        d16_l$clock = clock;
        d16_h$clock = clock;
        rn_3$clock = clock;
        lit_3$clock = clock;
        t_l$clock = clock;
        t_h$clock = clock;
        lit_4$clock = clock;
        idx_l$clock = clock;
        idx_h$clock = clock;
        lit_5$clock = clock;
        lit_6$clock = clock;
        diffuse_q$clock = clock;
        specular_q$clock = clock;
        n2_q$d = n2_q$q;
        dot_l$d = dot_l$q;
        dot_h$d = dot_h$q;
        rn$d = rn$q;
        d16_l$d = d16_l$q;
        d16_h$d = d16_h$q;
        rn_3$d = rn_3$q;
        lit_3$d = lit_3$q;
        t_l$d = t_l$q;
        t_h$d = t_h$q;
        lit_4$d = lit_4$q;
        idx_l$d = idx_l$q;
        idx_h$d = idx_h$q;
        lit_5$d = lit_5$q;
        lit_6$d = lit_6$q;
        diffuse_q$d = diffuse_q$q;
        specular_q$d = specular_q$q;
        regs$clock = clock;
        regs$host_write = host_write;
        regs$host_address = host_address;
        regs$host_data = host_data;
        diffuse_table$clock = clock;
        diffuse_table$host_write = host_write;
        diffuse_table$host_address = host_address;
        diffuse_table$host_data = host_data;
        specular_table$clock = clock;
        specular_table$host_write = host_write;
        specular_table$host_address = host_address;
        specular_table$host_data = host_data;
        qm$0 = 16'(q_mag$0);
        qm$1 = 16'(q_mag$1);
        qm$2 = 16'(q_mag$2);
        m_l$0 = regs$q$0[('h0)+:(16)];
        if (regs$q$0['hf]) begin
            m_l$0 = 'h0 - regs$q$0[('h0)+:(16)];
        end
        m_l$1 = regs$q$0[('h10)+:(16)];
        if (regs$q$0['h1f]) begin
            m_l$1 = 'h0 - regs$q$0[('h10)+:(16)];
        end
        m_l$2 = regs$q$0[('h20)+:(16)];
        if (regs$q$0['h2f]) begin
            m_l$2 = 'h0 - regs$q$0[('h20)+:(16)];
        end
        m_h$0 = regs$q$1[('h0)+:(16)];
        if (regs$q$1['hf]) begin
            m_h$0 = 'h0 - regs$q$1[('h0)+:(16)];
        end
        m_h$1 = regs$q$1[('h10)+:(16)];
        if (regs$q$1['h1f]) begin
            m_h$1 = 'h0 - regs$q$1[('h10)+:(16)];
        end
        m_h$2 = regs$q$1[('h20)+:(16)];
        if (regs$q$1['h2f]) begin
            m_h$2 = 'h0 - regs$q$1[('h20)+:(16)];
        end
        ml_q$0$clock = clock;
        mh_q$0$clock = clock;
        sl_q$0$clock = clock;
        sh_q$0$clock = clock;
        p_l$0$clock = clock;
        p_h$0$clock = clock;
        square$0$address = q_mag$0;
        ml_q$0$d = m_l$0;
        mh_q$0$d = m_h$0;
        p_l$0$d = qm$0 * ml_q$0$q;
        p_h$0$d = qm$0 * mh_q$0$q;
        ml_q$1$clock = clock;
        mh_q$1$clock = clock;
        sl_q$1$clock = clock;
        sh_q$1$clock = clock;
        p_l$1$clock = clock;
        p_h$1$clock = clock;
        square$1$address = q_mag$1;
        ml_q$1$d = m_l$1;
        mh_q$1$d = m_h$1;
        p_l$1$d = qm$1 * ml_q$1$q;
        p_h$1$d = qm$1 * mh_q$1$q;
        ml_q$2$clock = clock;
        mh_q$2$clock = clock;
        sl_q$2$clock = clock;
        sh_q$2$clock = clock;
        p_l$2$clock = clock;
        p_h$2$clock = clock;
        square$2$address = q_mag$2;
        ml_q$2$d = m_l$2;
        mh_q$2$d = m_h$2;
        p_l$2$d = qm$2 * ml_q$2$q;
        p_h$2$d = qm$2 * mh_q$2$q;
        sl_q$0$d = q_neg$0 ^ regs$q$0['hf];
        sl_q$1$d = q_neg$1 ^ regs$q$0['h1f];
        sl_q$2$d = q_neg$2 ^ regs$q$0['h2f];
        sh_q$0$d = q_neg$0 ^ regs$q$1['hf];
        sh_q$1$d = q_neg$1 ^ regs$q$1['h1f];
        sh_q$2$d = q_neg$2 ^ regs$q$1['h2f];
        n2 = 16'(square$0$data) + 16'(square$1$data) + 16'(square$2$data);
        n2_q$d = n2;
        t_pl$0 = p_l$0$q;
        if (sl_q$0$q) begin
            t_pl$0 = 'h0 - p_l$0$q;
        end
        t_ph$0 = p_h$0$q;
        if (sh_q$0$q) begin
            t_ph$0 = 'h0 - p_h$0$q;
        end
        t_pl$1 = p_l$1$q;
        if (sl_q$1$q) begin
            t_pl$1 = 'h0 - p_l$1$q;
        end
        t_ph$1 = p_h$1$q;
        if (sh_q$1$q) begin
            t_ph$1 = 'h0 - p_h$1$q;
        end
        t_pl$2 = p_l$2$q;
        if (sl_q$2$q) begin
            t_pl$2 = 'h0 - p_l$2$q;
        end
        t_ph$2 = p_h$2$q;
        if (sh_q$2$q) begin
            t_ph$2 = 'h0 - p_h$2$q;
        end
        dot_l$d = t_pl$0 + t_pl$1 + t_pl$2;
        dot_h$d = t_ph$0 + t_ph$1 + t_ph$2;
        rnorm$address = 10'(n2_q$q);
        rn$d = rnorm$data;
        d16_l$d = dot_l$q[('h0)+:(16)];
        if (dot_l$q['h1f] | (dot_l$q == 'h0)) begin
            d16_l$d = 'h0;
        end
        else if (dot_l$q > 'hffff) begin
            d16_l$d = 'hffff;
        end
        d16_h$d = dot_h$q[('h0)+:(16)];
        if (dot_h$q['h1f] | (dot_h$q == 'h0)) begin
            d16_h$d = 'h0;
        end
        else if (dot_h$q > 'hffff) begin
            d16_h$d = 'hffff;
        end
        rn_3$d = rn$q;
        lit_3$d = ~dot_l$q['h1f] & (dot_l$q != 'h0);
        t_l$d = d16_l$q * rn_3$q;
        t_h$d = d16_h$q * rn_3$q;
        lit_4$d = lit_3$q;
        i_l = ((64'(t_l$q) << 'ha) - 64'(t_l$q) + half_ulp) >> shift;
        if (i_l > last) begin
            i_l = last;
        end
        i_h = ((64'(t_h$q) << 'ha) - 64'(t_h$q) + half_ulp) >> shift;
        if (i_h > last) begin
            i_h = last;
        end
        idx_l$d = 10'(i_l);
        idx_h$d = 10'(i_h);
        lit_5$d = lit_4$q;
        diffuse_table$address = idx_l$q;
        specular_table$address = idx_h$q;
        lit_6$d = lit_5$q;
        diffuse_q$d = diffuse_table$data;
        specular_q$d = 'h0;
        if (lit_6$q) begin
            specular_q$d = specular_table$data;
        end
        diffuse = diffuse_q$q;
        specular = specular_q$q;
    end
    
endmodule // top$pipeline$shade$0$lighting
module top$pipeline$shade$0$lighting$d16_h(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$lighting$d16_h
module top$pipeline$shade$0$lighting$d16_l(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$lighting$d16_l
module top$pipeline$shade$0$lighting$diffuse_q(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$lighting$diffuse_q
module top$pipeline$shade$0$lighting$diffuse_table(clock,host_write,host_address,host_data,address,data);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  [9:0] address;
    output reg  [15:0] data;
    
    // Constant declarations
    localparam  base = 24'h30000;
    localparam  window = 24'h30400;
    
    // Stub signals
    reg  [9:0] ram$read_address;
    reg  ram$read_clock;
    wire  [15:0] ram$read_data;
    reg  [9:0] ram$write_address;
    reg  ram$write_clock;
    reg  [15:0] ram$write_data;
    reg  ram$write_enable;
    
    // Sub module instances
    top$pipeline$shade$0$lighting$diffuse_table$ram ram(
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
        ram$write_address = 10'(host_address - base);
        ram$write_data = 16'(host_data);
        ram$read_address = address;
        data = ram$read_data;
    end
    
endmodule // top$pipeline$shade$0$lighting$diffuse_table
module top$pipeline$shade$0$lighting$diffuse_table$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [9:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [9:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[1023:0];
    
    always @(posedge read_clock) begin
       read_data <= {8'd0, mem[read_address[9:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[9:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$pipeline$shade$0$lighting$diffuse_table$ram
module top$pipeline$shade$0$lighting$dot_h(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$lighting$dot_h
module top$pipeline$shade$0$lighting$dot_l(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$lighting$dot_l
module top$pipeline$shade$0$lighting$idx_h(d,q,clock);
    
    // Module arguments
    input wire  [9:0] d;
    output reg  [9:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 10'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$lighting$idx_h
module top$pipeline$shade$0$lighting$idx_l(d,q,clock);
    
    // Module arguments
    input wire  [9:0] d;
    output reg  [9:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 10'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$lighting$idx_l
module top$pipeline$shade$0$lighting$lit_3(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$lighting$lit_3
module top$pipeline$shade$0$lighting$lit_4(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$lighting$lit_4
module top$pipeline$shade$0$lighting$lit_5(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$lighting$lit_5
module top$pipeline$shade$0$lighting$lit_6(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$lighting$lit_6
module top$pipeline$shade$0$lighting$mh_q$0(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$lighting$mh_q$0
module top$pipeline$shade$0$lighting$mh_q$1(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$lighting$mh_q$1
module top$pipeline$shade$0$lighting$mh_q$2(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$lighting$mh_q$2
module top$pipeline$shade$0$lighting$ml_q$0(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$lighting$ml_q$0
module top$pipeline$shade$0$lighting$ml_q$1(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$lighting$ml_q$1
module top$pipeline$shade$0$lighting$ml_q$2(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$lighting$ml_q$2
module top$pipeline$shade$0$lighting$n2_q(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$lighting$n2_q
module top$pipeline$shade$0$lighting$p_h$0(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$lighting$p_h$0
module top$pipeline$shade$0$lighting$p_h$1(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$lighting$p_h$1
module top$pipeline$shade$0$lighting$p_h$2(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$lighting$p_h$2
module top$pipeline$shade$0$lighting$p_l$0(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$lighting$p_l$0
module top$pipeline$shade$0$lighting$p_l$1(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$lighting$p_l$1
module top$pipeline$shade$0$lighting$p_l$2(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$lighting$p_l$2
module top$pipeline$shade$0$lighting$regs(clock,host_write,host_address,host_data,q$0,q$1);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    output reg  [63:0] q$0;
    output reg  [63:0] q$1;
    
    // Constant declarations
    localparam  address$0 = 24'h10;
    localparam  address$1 = 24'h11;
    
    // Stub signals
    reg  [63:0] r$0$d;
    wire  [63:0] r$0$q;
    reg  r$0$clock;
    reg  [63:0] r$1$d;
    wire  [63:0] r$1$q;
    reg  r$1$clock;
    
    // Sub module instances
    top$pipeline$shade$0$lighting$regs$r$0 r$0(
        .d(r$0$d),
        .q(r$0$q),
        .clock(r$0$clock)
    );
    top$pipeline$shade$0$lighting$regs$r$1 r$1(
        .d(r$1$d),
        .q(r$1$q),
        .clock(r$1$clock)
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
    end
    
endmodule // top$pipeline$shade$0$lighting$regs
module top$pipeline$shade$0$lighting$regs$r$0(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$lighting$regs$r$0
module top$pipeline$shade$0$lighting$regs$r$1(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$lighting$regs$r$1
module top$pipeline$shade$0$lighting$rn(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$lighting$rn
module top$pipeline$shade$0$lighting$rn_3(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$lighting$rn_3
module top$pipeline$shade$0$lighting$rnorm(address,data);
    
    // Module arguments
    input wire  [9:0] address;
    output reg  [15:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        10'b0: data = 16'h0;
      10'b1: data = 16'h8000;
      10'b10: data = 16'h5a82;
      10'b11: data = 16'h49e7;
      10'b100: data = 16'h4000;
      10'b101: data = 16'h393e;
      10'b110: data = 16'h3441;
      10'b111: data = 16'h3061;
      10'b1000: data = 16'h2d41;
      10'b1001: data = 16'h2aab;
      10'b1010: data = 16'h287a;
      10'b1011: data = 16'h2698;
      10'b1100: data = 16'h24f3;
      10'b1101: data = 16'h2380;
      10'b1110: data = 16'h2236;
      10'b1111: data = 16'h210d;
      10'b10000: data = 16'h2000;
      10'b10001: data = 16'h1f0b;
      10'b10010: data = 16'h1e2b;
      10'b10011: data = 16'h1d5d;
      10'b10100: data = 16'h1c9f;
      10'b10101: data = 16'h1bef;
      10'b10110: data = 16'h1b4a;
      10'b10111: data = 16'h1ab1;
      10'b11000: data = 16'h1a21;
      10'b11001: data = 16'h199a;
      10'b11010: data = 16'h191a;
      10'b11011: data = 16'h18a2;
      10'b11100: data = 16'h1831;
      10'b11101: data = 16'h17c5;
      10'b11110: data = 16'h175f;
      10'b11111: data = 16'h16fd;
      10'b100000: data = 16'h16a1;
      10'b100001: data = 16'h1648;
      10'b100010: data = 16'h15f4;
      10'b100011: data = 16'h15a3;
      10'b100100: data = 16'h1555;
      10'b100101: data = 16'h150b;
      10'b100110: data = 16'h14c4;
      10'b100111: data = 16'h147f;
      10'b101000: data = 16'h143d;
      10'b101001: data = 16'h13fe;
      10'b101010: data = 16'h13c0;
      10'b101011: data = 16'h1385;
      10'b101100: data = 16'h134c;
      10'b101101: data = 16'h1315;
      10'b101110: data = 16'h12df;
      10'b101111: data = 16'h12ac;
      10'b110000: data = 16'h127a;
      10'b110001: data = 16'h1249;
      10'b110010: data = 16'h121a;
      10'b110011: data = 16'h11ec;
      10'b110100: data = 16'h11c0;
      10'b110101: data = 16'h1195;
      10'b110110: data = 16'h116b;
      10'b110111: data = 16'h1142;
      10'b111000: data = 16'h111b;
      10'b111001: data = 16'h10f4;
      10'b111010: data = 16'h10cf;
      10'b111011: data = 16'h10aa;
      10'b111100: data = 16'h1086;
      10'b111101: data = 16'h1064;
      10'b111110: data = 16'h1042;
      10'b111111: data = 16'h1020;
      10'b1000000: data = 16'h1000;
      10'b1000001: data = 16'hfe0;
      10'b1000010: data = 16'hfc1;
      10'b1000011: data = 16'hfa3;
      10'b1000100: data = 16'hf86;
      10'b1000101: data = 16'hf69;
      10'b1000110: data = 16'hf4d;
      10'b1000111: data = 16'hf31;
      10'b1001000: data = 16'hf16;
      10'b1001001: data = 16'hefb;
      10'b1001010: data = 16'hee1;
      10'b1001011: data = 16'hec8;
      10'b1001100: data = 16'heaf;
      10'b1001101: data = 16'he96;
      10'b1001110: data = 16'he7e;
      10'b1001111: data = 16'he67;
      10'b1010000: data = 16'he50;
      10'b1010001: data = 16'he39;
      10'b1010010: data = 16'he23;
      10'b1010011: data = 16'he0d;
      10'b1010100: data = 16'hdf7;
      10'b1010101: data = 16'hde2;
      10'b1010110: data = 16'hdcd;
      10'b1010111: data = 16'hdb9;
      10'b1011000: data = 16'hda5;
      10'b1011001: data = 16'hd91;
      10'b1011010: data = 16'hd7e;
      10'b1011011: data = 16'hd6b;
      10'b1011100: data = 16'hd58;
      10'b1011101: data = 16'hd46;
      10'b1011110: data = 16'hd34;
      10'b1011111: data = 16'hd22;
      10'b1100000: data = 16'hd10;
      10'b1100001: data = 16'hcff;
      10'b1100010: data = 16'hcee;
      10'b1100011: data = 16'hcdd;
      10'b1100100: data = 16'hccd;
      10'b1100101: data = 16'hcbd;
      10'b1100110: data = 16'hcad;
      10'b1100111: data = 16'hc9d;
      10'b1101000: data = 16'hc8d;
      10'b1101001: data = 16'hc7e;
      10'b1101010: data = 16'hc6f;
      10'b1101011: data = 16'hc60;
      10'b1101100: data = 16'hc51;
      10'b1101101: data = 16'hc43;
      10'b1101110: data = 16'hc34;
      10'b1101111: data = 16'hc26;
      10'b1110000: data = 16'hc18;
      10'b1110001: data = 16'hc0b;
      10'b1110010: data = 16'hbfd;
      10'b1110011: data = 16'hbf0;
      10'b1110100: data = 16'hbe2;
      10'b1110101: data = 16'hbd5;
      10'b1110110: data = 16'hbc9;
      10'b1110111: data = 16'hbbc;
      10'b1111000: data = 16'hbaf;
      10'b1111001: data = 16'hba3;
      10'b1111010: data = 16'hb97;
      10'b1111011: data = 16'hb8b;
      10'b1111100: data = 16'hb7f;
      10'b1111101: data = 16'hb73;
      10'b1111110: data = 16'hb67;
      10'b1111111: data = 16'hb5c;
      10'b10000000: data = 16'hb50;
      10'b10000001: data = 16'hb45;
      10'b10000010: data = 16'hb3a;
      10'b10000011: data = 16'hb2f;
      10'b10000100: data = 16'hb24;
      10'b10000101: data = 16'hb19;
      10'b10000110: data = 16'hb0f;
      10'b10000111: data = 16'hb04;
      10'b10001000: data = 16'hafa;
      10'b10001001: data = 16'haf0;
      10'b10001010: data = 16'hae5;
      10'b10001011: data = 16'hadb;
      10'b10001100: data = 16'had1;
      10'b10001101: data = 16'hac8;
      10'b10001110: data = 16'habe;
      10'b10001111: data = 16'hab4;
      10'b10010000: data = 16'haab;
      10'b10010001: data = 16'haa1;
      10'b10010010: data = 16'ha98;
      10'b10010011: data = 16'ha8f;
      10'b10010100: data = 16'ha86;
      10'b10010101: data = 16'ha7c;
      10'b10010110: data = 16'ha73;
      10'b10010111: data = 16'ha6b;
      10'b10011000: data = 16'ha62;
      10'b10011001: data = 16'ha59;
      10'b10011010: data = 16'ha51;
      10'b10011011: data = 16'ha48;
      10'b10011100: data = 16'ha40;
      10'b10011101: data = 16'ha37;
      10'b10011110: data = 16'ha2f;
      10'b10011111: data = 16'ha27;
      10'b10100000: data = 16'ha1f;
      10'b10100001: data = 16'ha16;
      10'b10100010: data = 16'ha0e;
      10'b10100011: data = 16'ha07;
      10'b10100100: data = 16'h9ff;
      10'b10100101: data = 16'h9f7;
      10'b10100110: data = 16'h9ef;
      10'b10100111: data = 16'h9e8;
      10'b10101000: data = 16'h9e0;
      10'b10101001: data = 16'h9d9;
      10'b10101010: data = 16'h9d1;
      10'b10101011: data = 16'h9ca;
      10'b10101100: data = 16'h9c3;
      10'b10101101: data = 16'h9bb;
      10'b10101110: data = 16'h9b4;
      10'b10101111: data = 16'h9ad;
      10'b10110000: data = 16'h9a6;
      10'b10110001: data = 16'h99f;
      10'b10110010: data = 16'h998;
      10'b10110011: data = 16'h991;
      10'b10110100: data = 16'h98a;
      10'b10110101: data = 16'h984;
      10'b10110110: data = 16'h97d;
      10'b10110111: data = 16'h976;
      10'b10111000: data = 16'h970;
      10'b10111001: data = 16'h969;
      10'b10111010: data = 16'h963;
      10'b10111011: data = 16'h95c;
      10'b10111100: data = 16'h956;
      10'b10111101: data = 16'h950;
      10'b10111110: data = 16'h949;
      10'b10111111: data = 16'h943;
      10'b11000000: data = 16'h93d;
      10'b11000001: data = 16'h937;
      10'b11000010: data = 16'h931;
      10'b11000011: data = 16'h92b;
      10'b11000100: data = 16'h925;
      10'b11000101: data = 16'h91f;
      10'b11000110: data = 16'h919;
      10'b11000111: data = 16'h913;
      10'b11001000: data = 16'h90d;
      10'b11001001: data = 16'h907;
      10'b11001010: data = 16'h902;
      10'b11001011: data = 16'h8fc;
      10'b11001100: data = 16'h8f6;
      10'b11001101: data = 16'h8f1;
      10'b11001110: data = 16'h8eb;
      10'b11001111: data = 16'h8e6;
      10'b11010000: data = 16'h8e0;
      10'b11010001: data = 16'h8db;
      10'b11010010: data = 16'h8d5;
      10'b11010011: data = 16'h8d0;
      10'b11010100: data = 16'h8cb;
      10'b11010101: data = 16'h8c5;
      10'b11010110: data = 16'h8c0;
      10'b11010111: data = 16'h8bb;
      10'b11011000: data = 16'h8b6;
      10'b11011001: data = 16'h8b0;
      10'b11011010: data = 16'h8ab;
      10'b11011011: data = 16'h8a6;
      10'b11011100: data = 16'h8a1;
      10'b11011101: data = 16'h89c;
      10'b11011110: data = 16'h897;
      10'b11011111: data = 16'h892;
      10'b11100000: data = 16'h88d;
      10'b11100001: data = 16'h889;
      10'b11100010: data = 16'h884;
      10'b11100011: data = 16'h87f;
      10'b11100100: data = 16'h87a;
      10'b11100101: data = 16'h875;
      10'b11100110: data = 16'h871;
      10'b11100111: data = 16'h86c;
      10'b11101000: data = 16'h867;
      10'b11101001: data = 16'h863;
      10'b11101010: data = 16'h85e;
      10'b11101011: data = 16'h85a;
      10'b11101100: data = 16'h855;
      10'b11101101: data = 16'h851;
      10'b11101110: data = 16'h84c;
      10'b11101111: data = 16'h848;
      10'b11110000: data = 16'h843;
      10'b11110001: data = 16'h83f;
      10'b11110010: data = 16'h83a;
      10'b11110011: data = 16'h836;
      10'b11110100: data = 16'h832;
      10'b11110101: data = 16'h82d;
      10'b11110110: data = 16'h829;
      10'b11110111: data = 16'h825;
      10'b11111000: data = 16'h821;
      10'b11111001: data = 16'h81d;
      10'b11111010: data = 16'h818;
      10'b11111011: data = 16'h814;
      10'b11111100: data = 16'h810;
      10'b11111101: data = 16'h80c;
      10'b11111110: data = 16'h808;
      10'b11111111: data = 16'h804;
      10'b100000000: data = 16'h800;
      10'b100000001: data = 16'h7fc;
      10'b100000010: data = 16'h7f8;
      10'b100000011: data = 16'h7f4;
      10'b100000100: data = 16'h7f0;
      10'b100000101: data = 16'h7ec;
      10'b100000110: data = 16'h7e8;
      10'b100000111: data = 16'h7e5;
      10'b100001000: data = 16'h7e1;
      10'b100001001: data = 16'h7dd;
      10'b100001010: data = 16'h7d9;
      10'b100001011: data = 16'h7d5;
      10'b100001100: data = 16'h7d2;
      10'b100001101: data = 16'h7ce;
      10'b100001110: data = 16'h7ca;
      10'b100001111: data = 16'h7c7;
      10'b100010000: data = 16'h7c3;
      10'b100010001: data = 16'h7bf;
      10'b100010010: data = 16'h7bc;
      10'b100010011: data = 16'h7b8;
      10'b100010100: data = 16'h7b4;
      10'b100010101: data = 16'h7b1;
      10'b100010110: data = 16'h7ad;
      10'b100010111: data = 16'h7aa;
      10'b100011000: data = 16'h7a6;
      10'b100011001: data = 16'h7a3;
      10'b100011010: data = 16'h79f;
      10'b100011011: data = 16'h79c;
      10'b100011100: data = 16'h798;
      10'b100011101: data = 16'h795;
      10'b100011110: data = 16'h792;
      10'b100011111: data = 16'h78e;
      10'b100100000: data = 16'h78b;
      10'b100100001: data = 16'h788;
      10'b100100010: data = 16'h784;
      10'b100100011: data = 16'h781;
      10'b100100100: data = 16'h77e;
      10'b100100101: data = 16'h77a;
      10'b100100110: data = 16'h777;
      10'b100100111: data = 16'h774;
      10'b100101000: data = 16'h771;
      10'b100101001: data = 16'h76d;
      10'b100101010: data = 16'h76a;
      10'b100101011: data = 16'h767;
      10'b100101100: data = 16'h764;
      10'b100101101: data = 16'h761;
      10'b100101110: data = 16'h75e;
      10'b100101111: data = 16'h75a;
      10'b100110000: data = 16'h757;
      10'b100110001: data = 16'h754;
      10'b100110010: data = 16'h751;
      10'b100110011: data = 16'h74e;
      10'b100110100: data = 16'h74b;
      10'b100110101: data = 16'h748;
      10'b100110110: data = 16'h745;
      10'b100110111: data = 16'h742;
      10'b100111000: data = 16'h73f;
      10'b100111001: data = 16'h73c;
      10'b100111010: data = 16'h739;
      10'b100111011: data = 16'h736;
      10'b100111100: data = 16'h733;
      10'b100111101: data = 16'h730;
      10'b100111110: data = 16'h72e;
      10'b100111111: data = 16'h72b;
      10'b101000000: data = 16'h728;
      10'b101000001: data = 16'h725;
      10'b101000010: data = 16'h722;
      10'b101000011: data = 16'h71f;
      10'b101000100: data = 16'h71c;
      10'b101000101: data = 16'h71a;
      10'b101000110: data = 16'h717;
      10'b101000111: data = 16'h714;
      10'b101001000: data = 16'h711;
      10'b101001001: data = 16'h70f;
      10'b101001010: data = 16'h70c;
      10'b101001011: data = 16'h709;
      10'b101001100: data = 16'h706;
      10'b101001101: data = 16'h704;
      10'b101001110: data = 16'h701;
      10'b101001111: data = 16'h6fe;
      10'b101010000: data = 16'h6fc;
      10'b101010001: data = 16'h6f9;
      10'b101010010: data = 16'h6f6;
      10'b101010011: data = 16'h6f4;
      10'b101010100: data = 16'h6f1;
      10'b101010101: data = 16'h6ee;
      10'b101010110: data = 16'h6ec;
      10'b101010111: data = 16'h6e9;
      10'b101011000: data = 16'h6e7;
      10'b101011001: data = 16'h6e4;
      10'b101011010: data = 16'h6e2;
      10'b101011011: data = 16'h6df;
      10'b101011100: data = 16'h6dd;
      10'b101011101: data = 16'h6da;
      10'b101011110: data = 16'h6d8;
      10'b101011111: data = 16'h6d5;
      10'b101100000: data = 16'h6d3;
      10'b101100001: data = 16'h6d0;
      10'b101100010: data = 16'h6ce;
      10'b101100011: data = 16'h6cb;
      10'b101100100: data = 16'h6c9;
      10'b101100101: data = 16'h6c6;
      10'b101100110: data = 16'h6c4;
      10'b101100111: data = 16'h6c1;
      10'b101101000: data = 16'h6bf;
      10'b101101001: data = 16'h6bd;
      10'b101101010: data = 16'h6ba;
      10'b101101011: data = 16'h6b8;
      10'b101101100: data = 16'h6b6;
      10'b101101101: data = 16'h6b3;
      10'b101101110: data = 16'h6b1;
      10'b101101111: data = 16'h6ae;
      10'b101110000: data = 16'h6ac;
      10'b101110001: data = 16'h6aa;
      10'b101110010: data = 16'h6a8;
      10'b101110011: data = 16'h6a5;
      10'b101110100: data = 16'h6a3;
      10'b101110101: data = 16'h6a1;
      10'b101110110: data = 16'h69e;
      10'b101110111: data = 16'h69c;
      10'b101111000: data = 16'h69a;
      10'b101111001: data = 16'h698;
      10'b101111010: data = 16'h695;
      10'b101111011: data = 16'h693;
      10'b101111100: data = 16'h691;
      10'b101111101: data = 16'h68f;
      10'b101111110: data = 16'h68d;
      10'b101111111: data = 16'h68a;
      10'b110000000: data = 16'h688;
      10'b110000001: data = 16'h686;
      10'b110000010: data = 16'h684;
      10'b110000011: data = 16'h682;
      10'b110000100: data = 16'h680;
      10'b110000101: data = 16'h67d;
      10'b110000110: data = 16'h67b;
      10'b110000111: data = 16'h679;
      10'b110001000: data = 16'h677;
      10'b110001001: data = 16'h675;
      10'b110001010: data = 16'h673;
      10'b110001011: data = 16'h671;
      10'b110001100: data = 16'h66f;
      10'b110001101: data = 16'h66d;
      10'b110001110: data = 16'h66b;
      10'b110001111: data = 16'h668;
      10'b110010000: data = 16'h666;
      10'b110010001: data = 16'h664;
      10'b110010010: data = 16'h662;
      10'b110010011: data = 16'h660;
      10'b110010100: data = 16'h65e;
      10'b110010101: data = 16'h65c;
      10'b110010110: data = 16'h65a;
      10'b110010111: data = 16'h658;
      10'b110011000: data = 16'h656;
      10'b110011001: data = 16'h654;
      10'b110011010: data = 16'h652;
      10'b110011011: data = 16'h650;
      10'b110011100: data = 16'h64e;
      10'b110011101: data = 16'h64c;
      10'b110011110: data = 16'h64a;
      10'b110011111: data = 16'h649;
      10'b110100000: data = 16'h647;
      10'b110100001: data = 16'h645;
      10'b110100010: data = 16'h643;
      10'b110100011: data = 16'h641;
      10'b110100100: data = 16'h63f;
      10'b110100101: data = 16'h63d;
      10'b110100110: data = 16'h63b;
      10'b110100111: data = 16'h639;
      10'b110101000: data = 16'h637;
      10'b110101001: data = 16'h635;
      10'b110101010: data = 16'h634;
      10'b110101011: data = 16'h632;
      10'b110101100: data = 16'h630;
      10'b110101101: data = 16'h62e;
      10'b110101110: data = 16'h62c;
      10'b110101111: data = 16'h62a;
      10'b110110000: data = 16'h629;
      10'b110110001: data = 16'h627;
      10'b110110010: data = 16'h625;
      10'b110110011: data = 16'h623;
      10'b110110100: data = 16'h621;
      10'b110110101: data = 16'h620;
      10'b110110110: data = 16'h61e;
      10'b110110111: data = 16'h61c;
      10'b110111000: data = 16'h61a;
      10'b110111001: data = 16'h618;
      10'b110111010: data = 16'h617;
      10'b110111011: data = 16'h615;
      10'b110111100: data = 16'h613;
      10'b110111101: data = 16'h611;
      10'b110111110: data = 16'h610;
      10'b110111111: data = 16'h60e;
      10'b111000000: data = 16'h60c;
      10'b111000001: data = 16'h60a;
      10'b111000010: data = 16'h609;
      10'b111000011: data = 16'h607;
      10'b111000100: data = 16'h605;
      10'b111000101: data = 16'h604;
      10'b111000110: data = 16'h602;
      10'b111000111: data = 16'h600;
      10'b111001000: data = 16'h5ff;
      10'b111001001: data = 16'h5fd;
      10'b111001010: data = 16'h5fb;
      10'b111001011: data = 16'h5f9;
      10'b111001100: data = 16'h5f8;
      10'b111001101: data = 16'h5f6;
      10'b111001110: data = 16'h5f5;
      10'b111001111: data = 16'h5f3;
      10'b111010000: data = 16'h5f1;
      10'b111010001: data = 16'h5f0;
      10'b111010010: data = 16'h5ee;
      10'b111010011: data = 16'h5ec;
      10'b111010100: data = 16'h5eb;
      10'b111010101: data = 16'h5e9;
      10'b111010110: data = 16'h5e7;
      10'b111010111: data = 16'h5e6;
      10'b111011000: data = 16'h5e4;
      10'b111011001: data = 16'h5e3;
      10'b111011010: data = 16'h5e1;
      10'b111011011: data = 16'h5df;
      10'b111011100: data = 16'h5de;
      10'b111011101: data = 16'h5dc;
      10'b111011110: data = 16'h5db;
      10'b111011111: data = 16'h5d9;
      10'b111100000: data = 16'h5d8;
      10'b111100001: data = 16'h5d6;
      10'b111100010: data = 16'h5d5;
      10'b111100011: data = 16'h5d3;
      10'b111100100: data = 16'h5d1;
      10'b111100101: data = 16'h5d0;
      10'b111100110: data = 16'h5ce;
      10'b111100111: data = 16'h5cd;
      10'b111101000: data = 16'h5cb;
      10'b111101001: data = 16'h5ca;
      10'b111101010: data = 16'h5c8;
      10'b111101011: data = 16'h5c7;
      10'b111101100: data = 16'h5c5;
      10'b111101101: data = 16'h5c4;
      10'b111101110: data = 16'h5c2;
      10'b111101111: data = 16'h5c1;
      10'b111110000: data = 16'h5bf;
      10'b111110001: data = 16'h5be;
      10'b111110010: data = 16'h5bc;
      10'b111110011: data = 16'h5bb;
      10'b111110100: data = 16'h5b9;
      10'b111110101: data = 16'h5b8;
      10'b111110110: data = 16'h5b7;
      10'b111110111: data = 16'h5b5;
      10'b111111000: data = 16'h5b4;
      10'b111111001: data = 16'h5b2;
      10'b111111010: data = 16'h5b1;
      10'b111111011: data = 16'h5af;
      10'b111111100: data = 16'h5ae;
      10'b111111101: data = 16'h5ac;
      10'b111111110: data = 16'h5ab;
      10'b111111111: data = 16'h5aa;
      10'b1000000000: data = 16'h5a8;
      10'b1000000001: data = 16'h5a7;
      10'b1000000010: data = 16'h5a5;
      10'b1000000011: data = 16'h5a4;
      10'b1000000100: data = 16'h5a3;
      10'b1000000101: data = 16'h5a1;
      10'b1000000110: data = 16'h5a0;
      10'b1000000111: data = 16'h59e;
      10'b1000001000: data = 16'h59d;
      10'b1000001001: data = 16'h59c;
      10'b1000001010: data = 16'h59a;
      10'b1000001011: data = 16'h599;
      10'b1000001100: data = 16'h597;
      10'b1000001101: data = 16'h596;
      10'b1000001110: data = 16'h595;
      10'b1000001111: data = 16'h593;
      10'b1000010000: data = 16'h592;
      10'b1000010001: data = 16'h591;
      10'b1000010010: data = 16'h58f;
      10'b1000010011: data = 16'h58e;
      10'b1000010100: data = 16'h58d;
      10'b1000010101: data = 16'h58b;
      10'b1000010110: data = 16'h58a;
      10'b1000010111: data = 16'h589;
      10'b1000011000: data = 16'h587;
      10'b1000011001: data = 16'h586;
      10'b1000011010: data = 16'h585;
      10'b1000011011: data = 16'h583;
      10'b1000011100: data = 16'h582;
      10'b1000011101: data = 16'h581;
      10'b1000011110: data = 16'h580;
      10'b1000011111: data = 16'h57e;
      10'b1000100000: data = 16'h57d;
      10'b1000100001: data = 16'h57c;
      10'b1000100010: data = 16'h57a;
      10'b1000100011: data = 16'h579;
      10'b1000100100: data = 16'h578;
      10'b1000100101: data = 16'h577;
      10'b1000100110: data = 16'h575;
      10'b1000100111: data = 16'h574;
      10'b1000101000: data = 16'h573;
      10'b1000101001: data = 16'h571;
      10'b1000101010: data = 16'h570;
      10'b1000101011: data = 16'h56f;
      10'b1000101100: data = 16'h56e;
      10'b1000101101: data = 16'h56c;
      10'b1000101110: data = 16'h56b;
      10'b1000101111: data = 16'h56a;
      10'b1000110000: data = 16'h569;
      10'b1000110001: data = 16'h567;
      10'b1000110010: data = 16'h566;
      10'b1000110011: data = 16'h565;
      10'b1000110100: data = 16'h564;
      10'b1000110101: data = 16'h563;
      10'b1000110110: data = 16'h561;
      10'b1000110111: data = 16'h560;
      10'b1000111000: data = 16'h55f;
      10'b1000111001: data = 16'h55e;
      10'b1000111010: data = 16'h55d;
      10'b1000111011: data = 16'h55b;
      10'b1000111100: data = 16'h55a;
      10'b1000111101: data = 16'h559;
      10'b1000111110: data = 16'h558;
      10'b1000111111: data = 16'h557;
      10'b1001000000: data = 16'h555;
      10'b1001000001: data = 16'h554;
      10'b1001000010: data = 16'h553;
      10'b1001000011: data = 16'h552;
      10'b1001000100: data = 16'h551;
      10'b1001000101: data = 16'h54f;
      10'b1001000110: data = 16'h54e;
      10'b1001000111: data = 16'h54d;
      10'b1001001000: data = 16'h54c;
      10'b1001001001: data = 16'h54b;
      10'b1001001010: data = 16'h54a;
      10'b1001001011: data = 16'h548;
      10'b1001001100: data = 16'h547;
      10'b1001001101: data = 16'h546;
      10'b1001001110: data = 16'h545;
      10'b1001001111: data = 16'h544;
      10'b1001010000: data = 16'h543;
      10'b1001010001: data = 16'h542;
      10'b1001010010: data = 16'h540;
      10'b1001010011: data = 16'h53f;
      10'b1001010100: data = 16'h53e;
      10'b1001010101: data = 16'h53d;
      10'b1001010110: data = 16'h53c;
      10'b1001010111: data = 16'h53b;
      10'b1001011000: data = 16'h53a;
      10'b1001011001: data = 16'h539;
      10'b1001011010: data = 16'h538;
      10'b1001011011: data = 16'h536;
      10'b1001011100: data = 16'h535;
      10'b1001011101: data = 16'h534;
      10'b1001011110: data = 16'h533;
      10'b1001011111: data = 16'h532;
      10'b1001100000: data = 16'h531;
      10'b1001100001: data = 16'h530;
      10'b1001100010: data = 16'h52f;
      10'b1001100011: data = 16'h52e;
      10'b1001100100: data = 16'h52d;
      10'b1001100101: data = 16'h52b;
      10'b1001100110: data = 16'h52a;
      10'b1001100111: data = 16'h529;
      10'b1001101000: data = 16'h528;
      10'b1001101001: data = 16'h527;
      10'b1001101010: data = 16'h526;
      10'b1001101011: data = 16'h525;
      10'b1001101100: data = 16'h524;
      10'b1001101101: data = 16'h523;
      10'b1001101110: data = 16'h522;
      10'b1001101111: data = 16'h521;
      10'b1001110000: data = 16'h520;
      10'b1001110001: data = 16'h51f;
      10'b1001110010: data = 16'h51e;
      10'b1001110011: data = 16'h51d;
      10'b1001110100: data = 16'h51c;
      10'b1001110101: data = 16'h51b;
      10'b1001110110: data = 16'h51a;
      10'b1001110111: data = 16'h518;
      10'b1001111000: data = 16'h517;
      10'b1001111001: data = 16'h516;
      10'b1001111010: data = 16'h515;
      10'b1001111011: data = 16'h514;
      10'b1001111100: data = 16'h513;
      10'b1001111101: data = 16'h512;
      10'b1001111110: data = 16'h511;
      10'b1001111111: data = 16'h510;
      10'b1010000000: data = 16'h50f;
      10'b1010000001: data = 16'h50e;
      10'b1010000010: data = 16'h50d;
      10'b1010000011: data = 16'h50c;
      10'b1010000100: data = 16'h50b;
      10'b1010000101: data = 16'h50a;
      10'b1010000110: data = 16'h509;
      10'b1010000111: data = 16'h508;
      10'b1010001000: data = 16'h507;
      10'b1010001001: data = 16'h506;
      10'b1010001010: data = 16'h505;
      10'b1010001011: data = 16'h504;
      10'b1010001100: data = 16'h503;
      10'b1010001101: data = 16'h502;
      10'b1010001110: data = 16'h501;
      10'b1010001111: data = 16'h500;
      10'b1010010000: data = 16'h4ff;
      10'b1010010001: data = 16'h4fe;
      10'b1010010010: data = 16'h4fd;
      10'b1010010011: data = 16'h4fc;
      10'b1010010100: data = 16'h4fb;
      10'b1010010101: data = 16'h4fb;
      10'b1010010110: data = 16'h4fa;
      10'b1010010111: data = 16'h4f9;
      10'b1010011000: data = 16'h4f8;
      10'b1010011001: data = 16'h4f7;
      10'b1010011010: data = 16'h4f6;
      10'b1010011011: data = 16'h4f5;
      10'b1010011100: data = 16'h4f4;
      10'b1010011101: data = 16'h4f3;
      10'b1010011110: data = 16'h4f2;
      10'b1010011111: data = 16'h4f1;
      10'b1010100000: data = 16'h4f0;
      10'b1010100001: data = 16'h4ef;
      10'b1010100010: data = 16'h4ee;
      10'b1010100011: data = 16'h4ed;
      10'b1010100100: data = 16'h4ec;
      10'b1010100101: data = 16'h4eb;
      10'b1010100110: data = 16'h4ea;
      10'b1010100111: data = 16'h4ea;
      10'b1010101000: data = 16'h4e9;
      10'b1010101001: data = 16'h4e8;
      10'b1010101010: data = 16'h4e7;
      10'b1010101011: data = 16'h4e6;
      10'b1010101100: data = 16'h4e5;
      10'b1010101101: data = 16'h4e4;
      10'b1010101110: data = 16'h4e3;
      10'b1010101111: data = 16'h4e2;
      10'b1010110000: data = 16'h4e1;
      10'b1010110001: data = 16'h4e0;
      10'b1010110010: data = 16'h4df;
      10'b1010110011: data = 16'h4df;
      10'b1010110100: data = 16'h4de;
      10'b1010110101: data = 16'h4dd;
      10'b1010110110: data = 16'h4dc;
      10'b1010110111: data = 16'h4db;
      10'b1010111000: data = 16'h4da;
      10'b1010111001: data = 16'h4d9;
      10'b1010111010: data = 16'h4d8;
      10'b1010111011: data = 16'h4d7;
      10'b1010111100: data = 16'h4d7;
      10'b1010111101: data = 16'h4d6;
      10'b1010111110: data = 16'h4d5;
      10'b1010111111: data = 16'h4d4;
      10'b1011000000: data = 16'h4d3;
      10'b1011000001: data = 16'h4d2;
      10'b1011000010: data = 16'h4d1;
      10'b1011000011: data = 16'h4d0;
      10'b1011000100: data = 16'h4cf;
      10'b1011000101: data = 16'h4cf;
      10'b1011000110: data = 16'h4ce;
      10'b1011000111: data = 16'h4cd;
      10'b1011001000: data = 16'h4cc;
      10'b1011001001: data = 16'h4cb;
      10'b1011001010: data = 16'h4ca;
      10'b1011001011: data = 16'h4c9;
      10'b1011001100: data = 16'h4c9;
      10'b1011001101: data = 16'h4c8;
      10'b1011001110: data = 16'h4c7;
      10'b1011001111: data = 16'h4c6;
      10'b1011010000: data = 16'h4c5;
      10'b1011010001: data = 16'h4c4;
      10'b1011010010: data = 16'h4c3;
      10'b1011010011: data = 16'h4c3;
      10'b1011010100: data = 16'h4c2;
      10'b1011010101: data = 16'h4c1;
      10'b1011010110: data = 16'h4c0;
      10'b1011010111: data = 16'h4bf;
      10'b1011011000: data = 16'h4be;
      10'b1011011001: data = 16'h4be;
      10'b1011011010: data = 16'h4bd;
      10'b1011011011: data = 16'h4bc;
      10'b1011011100: data = 16'h4bb;
      10'b1011011101: data = 16'h4ba;
      10'b1011011110: data = 16'h4b9;
      10'b1011011111: data = 16'h4b9;
      10'b1011100000: data = 16'h4b8;
      10'b1011100001: data = 16'h4b7;
      10'b1011100010: data = 16'h4b6;
      10'b1011100011: data = 16'h4b5;
      10'b1011100100: data = 16'h4b5;
      10'b1011100101: data = 16'h4b4;
      10'b1011100110: data = 16'h4b3;
      10'b1011100111: data = 16'h4b2;
      10'b1011101000: data = 16'h4b1;
      10'b1011101001: data = 16'h4b1;
      10'b1011101010: data = 16'h4b0;
      10'b1011101011: data = 16'h4af;
      10'b1011101100: data = 16'h4ae;
      10'b1011101101: data = 16'h4ad;
      10'b1011101110: data = 16'h4ad;
      10'b1011101111: data = 16'h4ac;
      10'b1011110000: data = 16'h4ab;
      10'b1011110001: data = 16'h4aa;
      10'b1011110010: data = 16'h4a9;
      10'b1011110011: data = 16'h4a9;
      10'b1011110100: data = 16'h4a8;
      10'b1011110101: data = 16'h4a7;
      10'b1011110110: data = 16'h4a6;
      10'b1011110111: data = 16'h4a5;
      10'b1011111000: data = 16'h4a5;
      10'b1011111001: data = 16'h4a4;
      10'b1011111010: data = 16'h4a3;
      10'b1011111011: data = 16'h4a2;
      10'b1011111100: data = 16'h4a2;
      10'b1011111101: data = 16'h4a1;
      10'b1011111110: data = 16'h4a0;
      10'b1011111111: data = 16'h49f;
      10'b1100000000: data = 16'h49e;
      10'b1100000001: data = 16'h49e;
      10'b1100000010: data = 16'h49d;
      10'b1100000011: data = 16'h49c;
      10'b1100000100: data = 16'h49b;
      10'b1100000101: data = 16'h49b;
      10'b1100000110: data = 16'h49a;
      10'b1100000111: data = 16'h499;
      10'b1100001000: data = 16'h498;
      10'b1100001001: data = 16'h498;
      10'b1100001010: data = 16'h497;
      10'b1100001011: data = 16'h496;
      10'b1100001100: data = 16'h495;
      10'b1100001101: data = 16'h495;
      10'b1100001110: data = 16'h494;
      10'b1100001111: data = 16'h493;
      10'b1100010000: data = 16'h492;
      10'b1100010001: data = 16'h492;
      10'b1100010010: data = 16'h491;
      10'b1100010011: data = 16'h490;
      10'b1100010100: data = 16'h48f;
      10'b1100010101: data = 16'h48f;
      10'b1100010110: data = 16'h48e;
      10'b1100010111: data = 16'h48d;
      10'b1100011000: data = 16'h48c;
      10'b1100011001: data = 16'h48c;
      10'b1100011010: data = 16'h48b;
      10'b1100011011: data = 16'h48a;
      10'b1100011100: data = 16'h489;
      10'b1100011101: data = 16'h489;
      10'b1100011110: data = 16'h488;
      10'b1100011111: data = 16'h487;
      10'b1100100000: data = 16'h487;
      10'b1100100001: data = 16'h486;
      10'b1100100010: data = 16'h485;
      10'b1100100011: data = 16'h484;
      10'b1100100100: data = 16'h484;
      10'b1100100101: data = 16'h483;
      10'b1100100110: data = 16'h482;
      10'b1100100111: data = 16'h481;
      10'b1100101000: data = 16'h481;
      10'b1100101001: data = 16'h480;
      10'b1100101010: data = 16'h47f;
      10'b1100101011: data = 16'h47f;
      10'b1100101100: data = 16'h47e;
      10'b1100101101: data = 16'h47d;
      10'b1100101110: data = 16'h47d;
      10'b1100101111: data = 16'h47c;
      10'b1100110000: data = 16'h47b;
      10'b1100110001: data = 16'h47a;
      10'b1100110010: data = 16'h47a;
      10'b1100110011: data = 16'h479;
      10'b1100110100: data = 16'h478;
      10'b1100110101: data = 16'h478;
      10'b1100110110: data = 16'h477;
      10'b1100110111: data = 16'h476;
      10'b1100111000: data = 16'h476;
      10'b1100111001: data = 16'h475;
      10'b1100111010: data = 16'h474;
      10'b1100111011: data = 16'h473;
      10'b1100111100: data = 16'h473;
      10'b1100111101: data = 16'h472;
      10'b1100111110: data = 16'h471;
      10'b1100111111: data = 16'h471;
      10'b1101000000: data = 16'h470;
      10'b1101000001: data = 16'h46f;
      10'b1101000010: data = 16'h46f;
      10'b1101000011: data = 16'h46e;
      10'b1101000100: data = 16'h46d;
      10'b1101000101: data = 16'h46d;
      10'b1101000110: data = 16'h46c;
      10'b1101000111: data = 16'h46b;
      10'b1101001000: data = 16'h46b;
      10'b1101001001: data = 16'h46a;
      10'b1101001010: data = 16'h469;
      10'b1101001011: data = 16'h469;
      10'b1101001100: data = 16'h468;
      10'b1101001101: data = 16'h467;
      10'b1101001110: data = 16'h467;
      10'b1101001111: data = 16'h466;
      10'b1101010000: data = 16'h465;
      10'b1101010001: data = 16'h465;
      10'b1101010010: data = 16'h464;
      10'b1101010011: data = 16'h463;
      10'b1101010100: data = 16'h463;
      10'b1101010101: data = 16'h462;
      10'b1101010110: data = 16'h461;
      10'b1101010111: data = 16'h461;
      10'b1101011000: data = 16'h460;
      10'b1101011001: data = 16'h45f;
      10'b1101011010: data = 16'h45f;
      10'b1101011011: data = 16'h45e;
      10'b1101011100: data = 16'h45d;
      10'b1101011101: data = 16'h45d;
      10'b1101011110: data = 16'h45c;
      10'b1101011111: data = 16'h45b;
      10'b1101100000: data = 16'h45b;
      10'b1101100001: data = 16'h45a;
      10'b1101100010: data = 16'h45a;
      10'b1101100011: data = 16'h459;
      10'b1101100100: data = 16'h458;
      10'b1101100101: data = 16'h458;
      10'b1101100110: data = 16'h457;
      10'b1101100111: data = 16'h456;
      10'b1101101000: data = 16'h456;
      10'b1101101001: data = 16'h455;
      10'b1101101010: data = 16'h454;
      10'b1101101011: data = 16'h454;
      10'b1101101100: data = 16'h453;
      10'b1101101101: data = 16'h452;
      10'b1101101110: data = 16'h452;
      10'b1101101111: data = 16'h451;
      10'b1101110000: data = 16'h451;
      10'b1101110001: data = 16'h450;
      10'b1101110010: data = 16'h44f;
      10'b1101110011: data = 16'h44f;
      10'b1101110100: data = 16'h44e;
      10'b1101110101: data = 16'h44d;
      10'b1101110110: data = 16'h44d;
      10'b1101110111: data = 16'h44c;
      10'b1101111000: data = 16'h44c;
      10'b1101111001: data = 16'h44b;
      10'b1101111010: data = 16'h44a;
      10'b1101111011: data = 16'h44a;
      10'b1101111100: data = 16'h449;
      10'b1101111101: data = 16'h449;
      10'b1101111110: data = 16'h448;
      10'b1101111111: data = 16'h447;
      10'b1110000000: data = 16'h447;
      10'b1110000001: data = 16'h446;
      10'b1110000010: data = 16'h445;
      10'b1110000011: data = 16'h445;
      10'b1110000100: data = 16'h444;
      10'b1110000101: data = 16'h444;
      10'b1110000110: data = 16'h443;
      10'b1110000111: data = 16'h442;
      10'b1110001000: data = 16'h442;
      10'b1110001001: data = 16'h441;
      10'b1110001010: data = 16'h441;
      10'b1110001011: data = 16'h440;
      10'b1110001100: data = 16'h43f;
      10'b1110001101: data = 16'h43f;
      10'b1110001110: data = 16'h43e;
      10'b1110001111: data = 16'h43e;
      10'b1110010000: data = 16'h43d;
      10'b1110010001: data = 16'h43c;
      10'b1110010010: data = 16'h43c;
      10'b1110010011: data = 16'h43b;
      10'b1110010100: data = 16'h43b;
      10'b1110010101: data = 16'h43a;
      10'b1110010110: data = 16'h43a;
      10'b1110010111: data = 16'h439;
      10'b1110011000: data = 16'h438;
      10'b1110011001: data = 16'h438;
      10'b1110011010: data = 16'h437;
      10'b1110011011: data = 16'h437;
      10'b1110011100: data = 16'h436;
      10'b1110011101: data = 16'h435;
      10'b1110011110: data = 16'h435;
      10'b1110011111: data = 16'h434;
      10'b1110100000: data = 16'h434;
      10'b1110100001: data = 16'h433;
      10'b1110100010: data = 16'h433;
      10'b1110100011: data = 16'h432;
      10'b1110100100: data = 16'h431;
      10'b1110100101: data = 16'h431;
      10'b1110100110: data = 16'h430;
      10'b1110100111: data = 16'h430;
      10'b1110101000: data = 16'h42f;
      10'b1110101001: data = 16'h42e;
      10'b1110101010: data = 16'h42e;
      10'b1110101011: data = 16'h42d;
      10'b1110101100: data = 16'h42d;
      10'b1110101101: data = 16'h42c;
      10'b1110101110: data = 16'h42c;
      10'b1110101111: data = 16'h42b;
      10'b1110110000: data = 16'h42b;
      10'b1110110001: data = 16'h42a;
      10'b1110110010: data = 16'h429;
      10'b1110110011: data = 16'h429;
      10'b1110110100: data = 16'h428;
      10'b1110110101: data = 16'h428;
      10'b1110110110: data = 16'h427;
      10'b1110110111: data = 16'h427;
      10'b1110111000: data = 16'h426;
      10'b1110111001: data = 16'h425;
      10'b1110111010: data = 16'h425;
      10'b1110111011: data = 16'h424;
      10'b1110111100: data = 16'h424;
      10'b1110111101: data = 16'h423;
      10'b1110111110: data = 16'h423;
      10'b1110111111: data = 16'h422;
      10'b1111000000: data = 16'h422;
      10'b1111000001: data = 16'h421;
      10'b1111000010: data = 16'h420;
      10'b1111000011: data = 16'h420;
      10'b1111000100: data = 16'h41f;
      10'b1111000101: data = 16'h41f;
      10'b1111000110: data = 16'h41e;
      10'b1111000111: data = 16'h41e;
      10'b1111001000: data = 16'h41d;
      10'b1111001001: data = 16'h41d;
      10'b1111001010: data = 16'h41c;
      10'b1111001011: data = 16'h41c;
      10'b1111001100: data = 16'h41b;
      10'b1111001101: data = 16'h41a;
      10'b1111001110: data = 16'h41a;
      10'b1111001111: data = 16'h419;
      10'b1111010000: data = 16'h419;
      10'b1111010001: data = 16'h418;
      10'b1111010010: data = 16'h418;
      10'b1111010011: data = 16'h417;
      10'b1111010100: data = 16'h417;
      10'b1111010101: data = 16'h416;
      10'b1111010110: data = 16'h416;
      10'b1111010111: data = 16'h415;
      10'b1111011000: data = 16'h415;
      10'b1111011001: data = 16'h414;
      10'b1111011010: data = 16'h414;
      10'b1111011011: data = 16'h413;
      10'b1111011100: data = 16'h412;
      10'b1111011101: data = 16'h412;
      10'b1111011110: data = 16'h411;
      10'b1111011111: data = 16'h411;
      10'b1111100000: data = 16'h410;
      10'b1111100001: data = 16'h410;
      10'b1111100010: data = 16'h40f;
      10'b1111100011: data = 16'h40f;
      10'b1111100100: data = 16'h40e;
      10'b1111100101: data = 16'h40e;
      10'b1111100110: data = 16'h40d;
      10'b1111100111: data = 16'h40d;
      10'b1111101000: data = 16'h40c;
      10'b1111101001: data = 16'h40c;
      10'b1111101010: data = 16'h40b;
      10'b1111101011: data = 16'h40b;
      10'b1111101100: data = 16'h40a;
      10'b1111101101: data = 16'h40a;
      10'b1111101110: data = 16'h409;
      10'b1111101111: data = 16'h409;
      10'b1111110000: data = 16'h408;
      10'b1111110001: data = 16'h408;
      10'b1111110010: data = 16'h407;
      10'b1111110011: data = 16'h407;
      10'b1111110100: data = 16'h406;
      10'b1111110101: data = 16'h406;
      10'b1111110110: data = 16'h405;
      10'b1111110111: data = 16'h405;
      10'b1111111000: data = 16'h404;
      10'b1111111001: data = 16'h404;
      10'b1111111010: data = 16'h403;
      10'b1111111011: data = 16'h403;
      10'b1111111100: data = 16'h402;
      10'b1111111101: data = 16'h402;
      10'b1111111110: data = 16'h401;
      10'b1111111111: data = 16'h401;
      default: data = 16'h0;
    endcase
            
endmodule // top$pipeline$shade$0$lighting$rnorm
module top$pipeline$shade$0$lighting$sh_q$0(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$lighting$sh_q$0
module top$pipeline$shade$0$lighting$sh_q$1(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$lighting$sh_q$1
module top$pipeline$shade$0$lighting$sh_q$2(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$lighting$sh_q$2
module top$pipeline$shade$0$lighting$sl_q$0(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$lighting$sl_q$0
module top$pipeline$shade$0$lighting$sl_q$1(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$lighting$sl_q$1
module top$pipeline$shade$0$lighting$sl_q$2(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$lighting$sl_q$2
module top$pipeline$shade$0$lighting$specular_q(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$lighting$specular_q
module top$pipeline$shade$0$lighting$specular_table(clock,host_write,host_address,host_data,address,data);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  [9:0] address;
    output reg  [15:0] data;
    
    // Constant declarations
    localparam  base = 24'h31000;
    localparam  window = 24'h31400;
    
    // Stub signals
    reg  [9:0] ram$read_address;
    reg  ram$read_clock;
    wire  [15:0] ram$read_data;
    reg  [9:0] ram$write_address;
    reg  ram$write_clock;
    reg  [15:0] ram$write_data;
    reg  ram$write_enable;
    
    // Sub module instances
    top$pipeline$shade$0$lighting$specular_table$ram ram(
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
        ram$write_address = 10'(host_address - base);
        ram$write_data = 16'(host_data);
        ram$read_address = address;
        data = ram$read_data;
    end
    
endmodule // top$pipeline$shade$0$lighting$specular_table
module top$pipeline$shade$0$lighting$specular_table$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [9:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [9:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[1023:0];
    
    always @(posedge read_clock) begin
       read_data <= {8'd0, mem[read_address[9:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[9:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$pipeline$shade$0$lighting$specular_table$ram
module top$pipeline$shade$0$lighting$square$0(address,data);
    
    // Module arguments
    input wire  [3:0] address;
    output reg  [7:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        4'h0: data = 8'h0;
      4'h1: data = 8'h1;
      4'h2: data = 8'h4;
      4'h3: data = 8'h9;
      4'h4: data = 8'h10;
      4'h5: data = 8'h19;
      4'h6: data = 8'h24;
      4'h7: data = 8'h31;
      4'h8: data = 8'h40;
      4'h9: data = 8'h51;
      4'ha: data = 8'h64;
      4'hb: data = 8'h79;
      4'hc: data = 8'h90;
      4'hd: data = 8'ha9;
      4'he: data = 8'hc4;
      4'hf: data = 8'he1;
      default: data = 8'h0;
    endcase
            
endmodule // top$pipeline$shade$0$lighting$square$0
module top$pipeline$shade$0$lighting$square$1(address,data);
    
    // Module arguments
    input wire  [3:0] address;
    output reg  [7:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        4'h0: data = 8'h0;
      4'h1: data = 8'h1;
      4'h2: data = 8'h4;
      4'h3: data = 8'h9;
      4'h4: data = 8'h10;
      4'h5: data = 8'h19;
      4'h6: data = 8'h24;
      4'h7: data = 8'h31;
      4'h8: data = 8'h40;
      4'h9: data = 8'h51;
      4'ha: data = 8'h64;
      4'hb: data = 8'h79;
      4'hc: data = 8'h90;
      4'hd: data = 8'ha9;
      4'he: data = 8'hc4;
      4'hf: data = 8'he1;
      default: data = 8'h0;
    endcase
            
endmodule // top$pipeline$shade$0$lighting$square$1
module top$pipeline$shade$0$lighting$square$2(address,data);
    
    // Module arguments
    input wire  [3:0] address;
    output reg  [7:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        4'h0: data = 8'h0;
      4'h1: data = 8'h1;
      4'h2: data = 8'h4;
      4'h3: data = 8'h9;
      4'h4: data = 8'h10;
      4'h5: data = 8'h19;
      4'h6: data = 8'h24;
      4'h7: data = 8'h31;
      4'h8: data = 8'h40;
      4'h9: data = 8'h51;
      4'ha: data = 8'h64;
      4'hb: data = 8'h79;
      4'hc: data = 8'h90;
      4'hd: data = 8'ha9;
      4'he: data = 8'hc4;
      4'hf: data = 8'he1;
      default: data = 8'h0;
    endcase
            
endmodule // top$pipeline$shade$0$lighting$square$2
module top$pipeline$shade$0$lighting$t_h(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$lighting$t_h
module top$pipeline$shade$0$lighting$t_l(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$lighting$t_l
module top$pipeline$shade$0$lit_b(clock,a,b,y);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  half = 'h80;
    localparam  shift = 8'h8;
    localparam  enabled = 1'b1;
    
    // Stub signals
    reg  [31:0] t$d;
    wire  [31:0] t$q;
    reg  t$clock;
    
    // Sub module instances
    top$pipeline$shade$0$lit_b$t t(
        .d(t$d),
        .q(t$q),
        .clock(t$clock)
    );
    
    // Update code
    reg  [15:0] y_pass;
    always @(*) begin
        t$clock = clock;
        t$d = t$q;
        t$d = a * b + half;
        y_pass = 16'((t$q + (t$q >> shift)) >> shift);
        if (~enabled) begin
            y_pass = 'h0;
        end
        y = y_pass;
    end
    
endmodule // top$pipeline$shade$0$lit_b
module top$pipeline$shade$0$lit_b$t(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$lit_b$t
module top$pipeline$shade$0$lit_g(clock,a,b,y);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  half = 'h80;
    localparam  shift = 8'h8;
    localparam  enabled = 1'b1;
    
    // Stub signals
    reg  [31:0] t$d;
    wire  [31:0] t$q;
    reg  t$clock;
    
    // Sub module instances
    top$pipeline$shade$0$lit_g$t t(
        .d(t$d),
        .q(t$q),
        .clock(t$clock)
    );
    
    // Update code
    reg  [15:0] y_pass;
    always @(*) begin
        t$clock = clock;
        t$d = t$q;
        t$d = a * b + half;
        y_pass = 16'((t$q + (t$q >> shift)) >> shift);
        if (~enabled) begin
            y_pass = 'h0;
        end
        y = y_pass;
    end
    
endmodule // top$pipeline$shade$0$lit_g
module top$pipeline$shade$0$lit_g$t(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$lit_g$t
module top$pipeline$shade$0$lit_r(clock,a,b,y);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  half = 'h80;
    localparam  shift = 8'h8;
    localparam  enabled = 1'b1;
    
    // Stub signals
    reg  [31:0] t$d;
    wire  [31:0] t$q;
    reg  t$clock;
    
    // Sub module instances
    top$pipeline$shade$0$lit_r$t t(
        .d(t$d),
        .q(t$q),
        .clock(t$clock)
    );
    
    // Update code
    reg  [15:0] y_pass;
    always @(*) begin
        t$clock = clock;
        t$d = t$q;
        t$d = a * b + half;
        y_pass = 16'((t$q + (t$q >> shift)) >> shift);
        if (~enabled) begin
            y_pass = 'h0;
        end
        y = y_pass;
    end
    
endmodule // top$pipeline$shade$0$lit_r
module top$pipeline$shade$0$lit_r$t(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$lit_r$t
module top$pipeline$shade$0$lut(clock,host_write,host_address,host_data,address,data);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  [11:0] address;
    output reg  [63:0] data;
    
    // Constant declarations
    localparam  base = 24'h10000;
    localparam  window = 24'h11000;
    
    // Stub signals
    reg  [11:0] ram$read_address;
    reg  ram$read_clock;
    wire  [63:0] ram$read_data;
    reg  [11:0] ram$write_address;
    reg  ram$write_clock;
    reg  [63:0] ram$write_data;
    reg  ram$write_enable;
    
    // Sub module instances
    top$pipeline$shade$0$lut$ram ram(
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
        ram$write_data = 64'(host_data);
        ram$read_address = address;
        data = ram$read_data;
    end
    
endmodule // top$pipeline$shade$0$lut
module top$pipeline$shade$0$lut$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [11:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [11:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [31:0] mem[255:0];
    
    always @(posedge read_clock) begin
       read_data <= {8'd0, mem[read_address[7:0]][31:24], 8'd0, mem[read_address[7:0]][23:16], 8'd0, mem[read_address[7:0]][15:8], 8'd0, mem[read_address[7:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[7:0]] <= {write_data[55:48], write_data[39:32], write_data[23:16], write_data[7:0]};
       end
    end
endmodule // top$pipeline$shade$0$lut$ram
module top$pipeline$shade$0$lut_q$0(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$lut_q$0
module top$pipeline$shade$0$lut_q$1(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$lut_q$1
module top$pipeline$shade$0$lut_q$2(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$lut_q$2
module top$pipeline$shade$0$lut_q$3(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$lut_q$3
module top$pipeline$shade$0$lut_q$4(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$lut_q$4
module top$pipeline$shade$0$lut_q$5(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$lut_q$5
module top$pipeline$shade$0$lut_q$6(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$lut_q$6
module top$pipeline$shade$0$lut_q$7(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$lut_q$7
module top$pipeline$shade$0$lut_q$8(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$lut_q$8
module top$pipeline$shade$0$mag_in$0(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$mag_in$0
module top$pipeline$shade$0$mag_in$1(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$mag_in$1
module top$pipeline$shade$0$mag_in$2(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$mag_in$2
module top$pipeline$shade$0$mul_b(clock,a,b,y);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  half = 'h80;
    localparam  shift = 8'h8;
    localparam  enabled = 1'b1;
    
    // Stub signals
    reg  [31:0] t$d;
    wire  [31:0] t$q;
    reg  t$clock;
    
    // Sub module instances
    top$pipeline$shade$0$mul_b$t t(
        .d(t$d),
        .q(t$q),
        .clock(t$clock)
    );
    
    // Update code
    reg  [15:0] y_pass;
    always @(*) begin
        t$clock = clock;
        t$d = t$q;
        t$d = a * b + half;
        y_pass = 16'((t$q + (t$q >> shift)) >> shift);
        if (~enabled) begin
            y_pass = 'h0;
        end
        y = y_pass;
    end
    
endmodule // top$pipeline$shade$0$mul_b
module top$pipeline$shade$0$mul_b$t(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$mul_b$t
module top$pipeline$shade$0$mul_g(clock,a,b,y);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  half = 'h80;
    localparam  shift = 8'h8;
    localparam  enabled = 1'b1;
    
    // Stub signals
    reg  [31:0] t$d;
    wire  [31:0] t$q;
    reg  t$clock;
    
    // Sub module instances
    top$pipeline$shade$0$mul_g$t t(
        .d(t$d),
        .q(t$q),
        .clock(t$clock)
    );
    
    // Update code
    reg  [15:0] y_pass;
    always @(*) begin
        t$clock = clock;
        t$d = t$q;
        t$d = a * b + half;
        y_pass = 16'((t$q + (t$q >> shift)) >> shift);
        if (~enabled) begin
            y_pass = 'h0;
        end
        y = y_pass;
    end
    
endmodule // top$pipeline$shade$0$mul_g
module top$pipeline$shade$0$mul_g$t(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$mul_g$t
module top$pipeline$shade$0$mul_r(clock,a,b,y);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  half = 'h80;
    localparam  shift = 8'h8;
    localparam  enabled = 1'b1;
    
    // Stub signals
    reg  [31:0] t$d;
    wire  [31:0] t$q;
    reg  t$clock;
    
    // Sub module instances
    top$pipeline$shade$0$mul_r$t t(
        .d(t$d),
        .q(t$q),
        .clock(t$clock)
    );
    
    // Update code
    reg  [15:0] y_pass;
    always @(*) begin
        t$clock = clock;
        t$d = t$q;
        t$d = a * b + half;
        y_pass = 16'((t$q + (t$q >> shift)) >> shift);
        if (~enabled) begin
            y_pass = 'h0;
        end
        y = y_pass;
    end
    
endmodule // top$pipeline$shade$0$mul_r
module top$pipeline$shade$0$mul_r$t(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$mul_r$t
module top$pipeline$shade$0$neg_in$0(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$neg_in$0
module top$pipeline$shade$0$neg_in$1(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$neg_in$1
module top$pipeline$shade$0$neg_in$2(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$neg_in$2
module top$pipeline$shade$0$normal(clock,neg$0,neg$1,neg$2,mag$0,mag$1,mag$2,q_neg$0,q_neg$1,q_neg$2,q_mag$0,q_mag$1,q_mag$2);
    
    // Module arguments
    input wire  clock;
    input wire  neg$0;
    input wire  neg$1;
    input wire  neg$2;
    input wire  [31:0] mag$0;
    input wire  [31:0] mag$1;
    input wire  [31:0] mag$2;
    output reg  q_neg$0;
    output reg  q_neg$1;
    output reg  q_neg$2;
    output reg  [3:0] q_mag$0;
    output reg  [3:0] q_mag$1;
    output reg  [3:0] q_mag$2;
    
    // Constant declarations
    localparam  bit_len$0 = 8'h1;
    localparam  bit_len$1 = 8'h2;
    localparam  bit_len$2 = 8'h3;
    localparam  bit_len$3 = 8'h4;
    localparam  bit_len$4 = 8'h5;
    localparam  bit_len$5 = 8'h6;
    localparam  bit_len$6 = 8'h7;
    localparam  bit_len$7 = 8'h8;
    localparam  bit_len$8 = 8'h9;
    localparam  bit_len$9 = 8'ha;
    localparam  bit_len$10 = 8'hb;
    localparam  bit_len$11 = 8'hc;
    localparam  bit_len$12 = 8'hd;
    localparam  bit_len$13 = 8'he;
    localparam  bit_len$14 = 8'hf;
    localparam  bit_len$15 = 8'h10;
    localparam  bit_len$16 = 8'h11;
    localparam  bit_len$17 = 8'h12;
    localparam  bit_len$18 = 8'h13;
    localparam  bit_len$19 = 8'h14;
    localparam  bit_len$20 = 8'h15;
    localparam  bit_len$21 = 8'h16;
    localparam  bit_len$22 = 8'h17;
    localparam  bit_len$23 = 8'h18;
    localparam  bit_len$24 = 8'h19;
    localparam  bit_len$25 = 8'h1a;
    localparam  bit_len$26 = 8'h1b;
    localparam  bit_len$27 = 8'h1c;
    localparam  bit_len$28 = 8'h1d;
    localparam  bit_len$29 = 8'h1e;
    localparam  bit_len$30 = 8'h1f;
    localparam  bit_len$31 = 8'h20;
    
    // Stub signals
    reg  [7:0] s_q$d;
    wire  [7:0] s_q$q;
    reg  s_q$clock;
    reg  neg_q$0$d;
    wire  neg_q$0$q;
    reg  neg_q$0$clock;
    reg  neg_q$1$d;
    wire  neg_q$1$q;
    reg  neg_q$1$clock;
    reg  neg_q$2$d;
    wire  neg_q$2$q;
    reg  neg_q$2$clock;
    reg  [31:0] mag_q$0$d;
    wire  [31:0] mag_q$0$q;
    reg  mag_q$0$clock;
    reg  [31:0] mag_q$1$d;
    wire  [31:0] mag_q$1$q;
    reg  mag_q$1$clock;
    reg  [31:0] mag_q$2$d;
    wire  [31:0] mag_q$2$q;
    reg  mag_q$2$clock;
    reg  [7:0] s_q2$d;
    wire  [7:0] s_q2$q;
    reg  s_q2$clock;
    reg  neg_q2$0$d;
    wire  neg_q2$0$q;
    reg  neg_q2$0$clock;
    reg  neg_q2$1$d;
    wire  neg_q2$1$q;
    reg  neg_q2$1$clock;
    reg  neg_q2$2$d;
    wire  neg_q2$2$q;
    reg  neg_q2$2$clock;
    reg  [31:0] sum_q$0$d;
    wire  [31:0] sum_q$0$q;
    reg  sum_q$0$clock;
    reg  [31:0] sum_q$1$d;
    wire  [31:0] sum_q$1$q;
    reg  sum_q$1$clock;
    reg  [31:0] sum_q$2$d;
    wire  [31:0] sum_q$2$q;
    reg  sum_q$2$clock;
    reg  out_neg$0$d;
    wire  out_neg$0$q;
    reg  out_neg$0$clock;
    reg  out_neg$1$d;
    wire  out_neg$1$q;
    reg  out_neg$1$clock;
    reg  out_neg$2$d;
    wire  out_neg$2$q;
    reg  out_neg$2$clock;
    reg  [3:0] out_mag$0$d;
    wire  [3:0] out_mag$0$q;
    reg  out_mag$0$clock;
    reg  [3:0] out_mag$1$d;
    wire  [3:0] out_mag$1$q;
    reg  out_mag$1$clock;
    reg  [3:0] out_mag$2$d;
    wire  [3:0] out_mag$2$q;
    reg  out_mag$2$clock;
    
    // Local signals
    reg  [31:0] m;
    reg  [7:0] bl;
    reg  [31:0] half;
    reg  [31:0] q$0;
    reg  [31:0] q$1;
    reg  [31:0] q$2;
    
    // Sub module instances
    top$pipeline$shade$0$normal$s_q s_q(
        .d(s_q$d),
        .q(s_q$q),
        .clock(s_q$clock)
    );
    top$pipeline$shade$0$normal$neg_q$0 neg_q$0(
        .d(neg_q$0$d),
        .q(neg_q$0$q),
        .clock(neg_q$0$clock)
    );
    top$pipeline$shade$0$normal$neg_q$1 neg_q$1(
        .d(neg_q$1$d),
        .q(neg_q$1$q),
        .clock(neg_q$1$clock)
    );
    top$pipeline$shade$0$normal$neg_q$2 neg_q$2(
        .d(neg_q$2$d),
        .q(neg_q$2$q),
        .clock(neg_q$2$clock)
    );
    top$pipeline$shade$0$normal$mag_q$0 mag_q$0(
        .d(mag_q$0$d),
        .q(mag_q$0$q),
        .clock(mag_q$0$clock)
    );
    top$pipeline$shade$0$normal$mag_q$1 mag_q$1(
        .d(mag_q$1$d),
        .q(mag_q$1$q),
        .clock(mag_q$1$clock)
    );
    top$pipeline$shade$0$normal$mag_q$2 mag_q$2(
        .d(mag_q$2$d),
        .q(mag_q$2$q),
        .clock(mag_q$2$clock)
    );
    top$pipeline$shade$0$normal$s_q2 s_q2(
        .d(s_q2$d),
        .q(s_q2$q),
        .clock(s_q2$clock)
    );
    top$pipeline$shade$0$normal$neg_q2$0 neg_q2$0(
        .d(neg_q2$0$d),
        .q(neg_q2$0$q),
        .clock(neg_q2$0$clock)
    );
    top$pipeline$shade$0$normal$neg_q2$1 neg_q2$1(
        .d(neg_q2$1$d),
        .q(neg_q2$1$q),
        .clock(neg_q2$1$clock)
    );
    top$pipeline$shade$0$normal$neg_q2$2 neg_q2$2(
        .d(neg_q2$2$d),
        .q(neg_q2$2$q),
        .clock(neg_q2$2$clock)
    );
    top$pipeline$shade$0$normal$sum_q$0 sum_q$0(
        .d(sum_q$0$d),
        .q(sum_q$0$q),
        .clock(sum_q$0$clock)
    );
    top$pipeline$shade$0$normal$sum_q$1 sum_q$1(
        .d(sum_q$1$d),
        .q(sum_q$1$q),
        .clock(sum_q$1$clock)
    );
    top$pipeline$shade$0$normal$sum_q$2 sum_q$2(
        .d(sum_q$2$d),
        .q(sum_q$2$q),
        .clock(sum_q$2$clock)
    );
    top$pipeline$shade$0$normal$out_neg$0 out_neg$0(
        .d(out_neg$0$d),
        .q(out_neg$0$q),
        .clock(out_neg$0$clock)
    );
    top$pipeline$shade$0$normal$out_neg$1 out_neg$1(
        .d(out_neg$1$d),
        .q(out_neg$1$q),
        .clock(out_neg$1$clock)
    );
    top$pipeline$shade$0$normal$out_neg$2 out_neg$2(
        .d(out_neg$2$d),
        .q(out_neg$2$q),
        .clock(out_neg$2$clock)
    );
    top$pipeline$shade$0$normal$out_mag$0 out_mag$0(
        .d(out_mag$0$d),
        .q(out_mag$0$q),
        .clock(out_mag$0$clock)
    );
    top$pipeline$shade$0$normal$out_mag$1 out_mag$1(
        .d(out_mag$1$d),
        .q(out_mag$1$q),
        .clock(out_mag$1$clock)
    );
    top$pipeline$shade$0$normal$out_mag$2 out_mag$2(
        .d(out_mag$2$d),
        .q(out_mag$2$q),
        .clock(out_mag$2$clock)
    );
    
    // Update code
    always @(*) begin
        s_q$clock = clock;
        s_q2$clock = clock;
        s_q$d = s_q$q;
        s_q2$d = s_q2$q;
        m = mag$0 | mag$1 | mag$2;
        bl = 'h0;
        if (m[0]) begin
            bl = bit_len$0;
        end
        if (m[1]) begin
            bl = bit_len$1;
        end
        if (m[2]) begin
            bl = bit_len$2;
        end
        if (m[3]) begin
            bl = bit_len$3;
        end
        if (m[4]) begin
            bl = bit_len$4;
        end
        if (m[5]) begin
            bl = bit_len$5;
        end
        if (m[6]) begin
            bl = bit_len$6;
        end
        if (m[7]) begin
            bl = bit_len$7;
        end
        if (m[8]) begin
            bl = bit_len$8;
        end
        if (m[9]) begin
            bl = bit_len$9;
        end
        if (m[10]) begin
            bl = bit_len$10;
        end
        if (m[11]) begin
            bl = bit_len$11;
        end
        if (m[12]) begin
            bl = bit_len$12;
        end
        if (m[13]) begin
            bl = bit_len$13;
        end
        if (m[14]) begin
            bl = bit_len$14;
        end
        if (m[15]) begin
            bl = bit_len$15;
        end
        if (m[16]) begin
            bl = bit_len$16;
        end
        if (m[17]) begin
            bl = bit_len$17;
        end
        if (m[18]) begin
            bl = bit_len$18;
        end
        if (m[19]) begin
            bl = bit_len$19;
        end
        if (m[20]) begin
            bl = bit_len$20;
        end
        if (m[21]) begin
            bl = bit_len$21;
        end
        if (m[22]) begin
            bl = bit_len$22;
        end
        if (m[23]) begin
            bl = bit_len$23;
        end
        if (m[24]) begin
            bl = bit_len$24;
        end
        if (m[25]) begin
            bl = bit_len$25;
        end
        if (m[26]) begin
            bl = bit_len$26;
        end
        if (m[27]) begin
            bl = bit_len$27;
        end
        if (m[28]) begin
            bl = bit_len$28;
        end
        if (m[29]) begin
            bl = bit_len$29;
        end
        if (m[30]) begin
            bl = bit_len$30;
        end
        if (m[31]) begin
            bl = bit_len$31;
        end
        s_q$d = 'h0;
        if (bl > 'h4) begin
            s_q$d = bl - 'h4;
        end
        half = 'h0;
        if (s_q$q > 'h0) begin
            half = (32'('h1) << s_q$q) >> 'h1;
        end
        s_q2$d = s_q$q;
        neg_q$0$clock = clock;
        mag_q$0$clock = clock;
        neg_q2$0$clock = clock;
        sum_q$0$clock = clock;
        out_neg$0$clock = clock;
        out_mag$0$clock = clock;
        neg_q$0$d = neg$0;
        mag_q$0$d = mag$0;
        neg_q2$0$d = neg_q$0$q;
        sum_q$0$d = mag_q$0$q + half;
        if (neg_q$0$q & (s_q$q > 'h0)) begin
            sum_q$0$d = mag_q$0$q + half - 'h1;
        end
        q$0 = sum_q$0$q >> s_q2$q;
        if (q$0 > 'hf) begin
            q$0 = 'hf;
        end
        out_mag$0$d = q$0[('h0)+:(4)];
        out_neg$0$d = neg_q2$0$q & (q$0 != 'h0);
        q_neg$0 = out_neg$0$q;
        q_mag$0 = out_mag$0$q;
        neg_q$1$clock = clock;
        mag_q$1$clock = clock;
        neg_q2$1$clock = clock;
        sum_q$1$clock = clock;
        out_neg$1$clock = clock;
        out_mag$1$clock = clock;
        neg_q$1$d = neg$1;
        mag_q$1$d = mag$1;
        neg_q2$1$d = neg_q$1$q;
        sum_q$1$d = mag_q$1$q + half;
        if (neg_q$1$q & (s_q$q > 'h0)) begin
            sum_q$1$d = mag_q$1$q + half - 'h1;
        end
        q$1 = sum_q$1$q >> s_q2$q;
        if (q$1 > 'hf) begin
            q$1 = 'hf;
        end
        out_mag$1$d = q$1[('h0)+:(4)];
        out_neg$1$d = neg_q2$1$q & (q$1 != 'h0);
        q_neg$1 = out_neg$1$q;
        q_mag$1 = out_mag$1$q;
        neg_q$2$clock = clock;
        mag_q$2$clock = clock;
        neg_q2$2$clock = clock;
        sum_q$2$clock = clock;
        out_neg$2$clock = clock;
        out_mag$2$clock = clock;
        neg_q$2$d = neg$2;
        mag_q$2$d = mag$2;
        neg_q2$2$d = neg_q$2$q;
        sum_q$2$d = mag_q$2$q + half;
        if (neg_q$2$q & (s_q$q > 'h0)) begin
            sum_q$2$d = mag_q$2$q + half - 'h1;
        end
        q$2 = sum_q$2$q >> s_q2$q;
        if (q$2 > 'hf) begin
            q$2 = 'hf;
        end
        out_mag$2$d = q$2[('h0)+:(4)];
        out_neg$2$d = neg_q2$2$q & (q$2 != 'h0);
        q_neg$2 = out_neg$2$q;
        q_mag$2 = out_mag$2$q;
    end
    
endmodule // top$pipeline$shade$0$normal
module top$pipeline$shade$0$normal$mag_q$0(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$normal$mag_q$0
module top$pipeline$shade$0$normal$mag_q$1(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$normal$mag_q$1
module top$pipeline$shade$0$normal$mag_q$2(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$normal$mag_q$2
module top$pipeline$shade$0$normal$neg_q$0(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$normal$neg_q$0
module top$pipeline$shade$0$normal$neg_q$1(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$normal$neg_q$1
module top$pipeline$shade$0$normal$neg_q$2(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$normal$neg_q$2
module top$pipeline$shade$0$normal$neg_q2$0(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$normal$neg_q2$0
module top$pipeline$shade$0$normal$neg_q2$1(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$normal$neg_q2$1
module top$pipeline$shade$0$normal$neg_q2$2(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$normal$neg_q2$2
module top$pipeline$shade$0$normal$out_mag$0(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$normal$out_mag$0
module top$pipeline$shade$0$normal$out_mag$1(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$normal$out_mag$1
module top$pipeline$shade$0$normal$out_mag$2(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$normal$out_mag$2
module top$pipeline$shade$0$normal$out_neg$0(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$normal$out_neg$0
module top$pipeline$shade$0$normal$out_neg$1(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$normal$out_neg$1
module top$pipeline$shade$0$normal$out_neg$2(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$normal$out_neg$2
module top$pipeline$shade$0$normal$s_q(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$normal$s_q
module top$pipeline$shade$0$normal$s_q2(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$normal$s_q2
module top$pipeline$shade$0$normal$sum_q$0(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$normal$sum_q$0
module top$pipeline$shade$0$normal$sum_q$1(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$normal$sum_q$1
module top$pipeline$shade$0$normal$sum_q$2(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$normal$sum_q$2
module top$pipeline$shade$0$r_q(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$r_q
module top$pipeline$shade$0$row_q$0(d,q,clock);
    
    // Module arguments
    input wire  [11:0] d;
    output reg  [11:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 12'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$row_q$0
module top$pipeline$shade$0$row_q$1(d,q,clock);
    
    // Module arguments
    input wire  [11:0] d;
    output reg  [11:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 12'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$row_q$1
module top$pipeline$shade$0$row_q$2(d,q,clock);
    
    // Module arguments
    input wire  [11:0] d;
    output reg  [11:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 12'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$row_q$2
module top$pipeline$shade$0$row_q$3(d,q,clock);
    
    // Module arguments
    input wire  [11:0] d;
    output reg  [11:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 12'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$0$row_q$3
module top$pipeline$shade$0$shaded_q$0(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$shaded_q$0
module top$pipeline$shade$0$shaded_q$1(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$shaded_q$1
module top$pipeline$shade$0$shaded_q$2(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$shaded_q$2
module top$pipeline$shade$0$specular_q(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$specular_q
module top$pipeline$shade$0$valid_q$0(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$valid_q$0
module top$pipeline$shade$0$valid_q$1(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$valid_q$1
module top$pipeline$shade$0$valid_q$10(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$valid_q$10
module top$pipeline$shade$0$valid_q$11(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$valid_q$11
module top$pipeline$shade$0$valid_q$12(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$valid_q$12
module top$pipeline$shade$0$valid_q$13(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$valid_q$13
module top$pipeline$shade$0$valid_q$14(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$valid_q$14
module top$pipeline$shade$0$valid_q$2(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$valid_q$2
module top$pipeline$shade$0$valid_q$3(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$valid_q$3
module top$pipeline$shade$0$valid_q$4(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$valid_q$4
module top$pipeline$shade$0$valid_q$5(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$valid_q$5
module top$pipeline$shade$0$valid_q$6(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$valid_q$6
module top$pipeline$shade$0$valid_q$7(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$valid_q$7
module top$pipeline$shade$0$valid_q$8(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$valid_q$8
module top$pipeline$shade$0$valid_q$9(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$valid_q$9
module top$pipeline$shade$0$value_q$0(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$value_q$0
module top$pipeline$shade$0$value_q$1(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$value_q$1
module top$pipeline$shade$0$value_q$10(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$value_q$10
module top$pipeline$shade$0$value_q$11(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$value_q$11
module top$pipeline$shade$0$value_q$12(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$value_q$12
module top$pipeline$shade$0$value_q$13(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$value_q$13
module top$pipeline$shade$0$value_q$2(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$value_q$2
module top$pipeline$shade$0$value_q$3(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$value_q$3
module top$pipeline$shade$0$value_q$4(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$value_q$4
module top$pipeline$shade$0$value_q$5(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$value_q$5
module top$pipeline$shade$0$value_q$6(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$value_q$6
module top$pipeline$shade$0$value_q$7(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$value_q$7
module top$pipeline$shade$0$value_q$8(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$value_q$8
module top$pipeline$shade$0$value_q$9(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$0$value_q$9
module top$pipeline$shade$1(clock,host_write,host_address,host_data,value,invalid,at_edge,gx_neg,gx_mag,gy_neg,gy_mag,gz_neg,gz_mag,r,g,b,a,valid);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  [15:0] value;
    input wire  invalid;
    input wire  at_edge;
    input wire  gx_neg;
    input wire  [31:0] gx_mag;
    input wire  gy_neg;
    input wire  [31:0] gy_mag;
    input wire  gz_neg;
    input wire  [31:0] gz_mag;
    output reg  [31:0] r;
    output reg  [15:0] g;
    output reg  [15:0] b;
    output reg  [15:0] a;
    output reg  valid;
    
    // Constant declarations
    localparam  gm_on = 1'b0;
    localparam  scalar = 1'b0;
    localparam  xray = 1'b0;
    localparam  shaded = 1'b1;
    localparam  edge_transparent = 1'b1;
    localparam  shift = 8'h0;
    localparam  m_max = 16'hff;
    localparam  enabled = 1'b1;
    
    // Stub signals
    reg  lut$clock;
    reg  lut$host_write;
    reg  [23:0] lut$host_address;
    reg  [63:0] lut$host_data;
    reg  [11:0] lut$address;
    wire  [63:0] lut$data;
    reg  alpha_gm$clock;
    reg  alpha_gm$host_write;
    reg  [23:0] alpha_gm$host_address;
    reg  [63:0] alpha_gm$host_data;
    reg  [15:0] alpha_gm$address;
    wire  [15:0] alpha_gm$data = 'h0;
    reg  gm_bin$clock;
    reg  gm_bin$host_write;
    reg  [23:0] gm_bin$host_address;
    reg  [63:0] gm_bin$host_data;
    reg  [31:0] gm_bin$mag$0;
    reg  [31:0] gm_bin$mag$1;
    reg  [31:0] gm_bin$mag$2;
    wire  [3:0] gm_bin$bin = 'h0;
    reg  normal$clock;
    reg  normal$neg$0;
    reg  normal$neg$1;
    reg  normal$neg$2;
    reg  [31:0] normal$mag$0;
    reg  [31:0] normal$mag$1;
    reg  [31:0] normal$mag$2;
    wire  normal$q_neg$0;
    wire  normal$q_neg$1;
    wire  normal$q_neg$2;
    wire  [3:0] normal$q_mag$0;
    wire  [3:0] normal$q_mag$1;
    wire  [3:0] normal$q_mag$2;
    reg  lighting$clock;
    reg  lighting$host_write;
    reg  [23:0] lighting$host_address;
    reg  [63:0] lighting$host_data;
    reg  lighting$q_neg$0;
    reg  lighting$q_neg$1;
    reg  lighting$q_neg$2;
    reg  [3:0] lighting$q_mag$0;
    reg  [3:0] lighting$q_mag$1;
    reg  [3:0] lighting$q_mag$2;
    wire  [15:0] lighting$diffuse;
    wire  [15:0] lighting$specular;
    reg  neg_in$0$d;
    wire  neg_in$0$q;
    reg  neg_in$0$clock;
    reg  neg_in$1$d;
    wire  neg_in$1$q;
    reg  neg_in$1$clock;
    reg  neg_in$2$d;
    wire  neg_in$2$q;
    reg  neg_in$2$clock;
    reg  [31:0] mag_in$0$d;
    wire  [31:0] mag_in$0$q;
    reg  mag_in$0$clock;
    reg  [31:0] mag_in$1$d;
    wire  [31:0] mag_in$1$q;
    reg  mag_in$1$clock;
    reg  [31:0] mag_in$2$d;
    wire  [31:0] mag_in$2$q;
    reg  mag_in$2$clock;
    reg  [11:0] row_q$0$d;
    wire  [11:0] row_q$0$q;
    reg  row_q$0$clock;
    reg  [11:0] row_q$1$d;
    wire  [11:0] row_q$1$q;
    reg  row_q$1$clock;
    reg  [11:0] row_q$2$d;
    wire  [11:0] row_q$2$q;
    reg  row_q$2$clock;
    reg  [11:0] row_q$3$d;
    wire  [11:0] row_q$3$q;
    reg  row_q$3$clock;
    reg  [63:0] lut_q$0$d;
    wire  [63:0] lut_q$0$q;
    reg  lut_q$0$clock;
    reg  [63:0] lut_q$1$d;
    wire  [63:0] lut_q$1$q;
    reg  lut_q$1$clock;
    reg  [63:0] lut_q$2$d;
    wire  [63:0] lut_q$2$q;
    reg  lut_q$2$clock;
    reg  [63:0] lut_q$3$d;
    wire  [63:0] lut_q$3$q;
    reg  lut_q$3$clock;
    reg  [63:0] lut_q$4$d;
    wire  [63:0] lut_q$4$q;
    reg  lut_q$4$clock;
    reg  [63:0] lut_q$5$d;
    wire  [63:0] lut_q$5$q;
    reg  lut_q$5$clock;
    reg  [63:0] lut_q$6$d;
    wire  [63:0] lut_q$6$q;
    reg  lut_q$6$clock;
    reg  [63:0] lut_q$7$d;
    wire  [63:0] lut_q$7$q;
    reg  lut_q$7$clock;
    reg  [63:0] lut_q$8$d;
    wire  [63:0] lut_q$8$q;
    reg  lut_q$8$clock;
    reg  gate_q$0$d;
    wire  gate_q$0$q;
    reg  gate_q$0$clock;
    reg  gate_q$1$d;
    wire  gate_q$1$q;
    reg  gate_q$1$clock;
    reg  gate_q$2$d;
    wire  gate_q$2$q;
    reg  gate_q$2$clock;
    reg  gate_q$3$d;
    wire  gate_q$3$q;
    reg  gate_q$3$clock;
    reg  gate_q$4$d;
    wire  gate_q$4$q;
    reg  gate_q$4$clock;
    reg  [15:0] alpha_q$0$d;
    wire  [15:0] alpha_q$0$q;
    reg  alpha_q$0$clock;
    reg  [15:0] alpha_q$1$d;
    wire  [15:0] alpha_q$1$q;
    reg  alpha_q$1$clock;
    reg  [15:0] alpha_q$2$d;
    wire  [15:0] alpha_q$2$q;
    reg  alpha_q$2$clock;
    reg  [15:0] alpha_q$3$d;
    wire  [15:0] alpha_q$3$q;
    reg  alpha_q$3$clock;
    reg  [15:0] alpha_q$4$d;
    wire  [15:0] alpha_q$4$q;
    reg  alpha_q$4$clock;
    reg  [15:0] alpha_q$5$d;
    wire  [15:0] alpha_q$5$q;
    reg  alpha_q$5$clock;
    reg  [15:0] alpha_q$6$d;
    wire  [15:0] alpha_q$6$q;
    reg  alpha_q$6$clock;
    reg  [15:0] alpha_q$7$d;
    wire  [15:0] alpha_q$7$q;
    reg  alpha_q$7$clock;
    reg  [15:0] alpha_q$8$d;
    wire  [15:0] alpha_q$8$q;
    reg  alpha_q$8$clock;
    reg  [15:0] value_q$0$d;
    wire  [15:0] value_q$0$q;
    reg  value_q$0$clock;
    reg  [15:0] value_q$1$d;
    wire  [15:0] value_q$1$q;
    reg  value_q$1$clock;
    reg  [15:0] value_q$2$d;
    wire  [15:0] value_q$2$q;
    reg  value_q$2$clock;
    reg  [15:0] value_q$3$d;
    wire  [15:0] value_q$3$q;
    reg  value_q$3$clock;
    reg  [15:0] value_q$4$d;
    wire  [15:0] value_q$4$q;
    reg  value_q$4$clock;
    reg  [15:0] value_q$5$d;
    wire  [15:0] value_q$5$q;
    reg  value_q$5$clock;
    reg  [15:0] value_q$6$d;
    wire  [15:0] value_q$6$q;
    reg  value_q$6$clock;
    reg  [15:0] value_q$7$d;
    wire  [15:0] value_q$7$q;
    reg  value_q$7$clock;
    reg  [15:0] value_q$8$d;
    wire  [15:0] value_q$8$q;
    reg  value_q$8$clock;
    reg  [15:0] value_q$9$d;
    wire  [15:0] value_q$9$q;
    reg  value_q$9$clock;
    reg  [15:0] value_q$10$d;
    wire  [15:0] value_q$10$q;
    reg  value_q$10$clock;
    reg  [15:0] value_q$11$d;
    wire  [15:0] value_q$11$q;
    reg  value_q$11$clock;
    reg  [15:0] value_q$12$d;
    wire  [15:0] value_q$12$q;
    reg  value_q$12$clock;
    reg  [15:0] value_q$13$d;
    wire  [15:0] value_q$13$q;
    reg  value_q$13$clock;
    reg  valid_q$0$d;
    wire  valid_q$0$q;
    reg  valid_q$0$clock;
    reg  valid_q$1$d;
    wire  valid_q$1$q;
    reg  valid_q$1$clock;
    reg  valid_q$2$d;
    wire  valid_q$2$q;
    reg  valid_q$2$clock;
    reg  valid_q$3$d;
    wire  valid_q$3$q;
    reg  valid_q$3$clock;
    reg  valid_q$4$d;
    wire  valid_q$4$q;
    reg  valid_q$4$clock;
    reg  valid_q$5$d;
    wire  valid_q$5$q;
    reg  valid_q$5$clock;
    reg  valid_q$6$d;
    wire  valid_q$6$q;
    reg  valid_q$6$clock;
    reg  valid_q$7$d;
    wire  valid_q$7$q;
    reg  valid_q$7$clock;
    reg  valid_q$8$d;
    wire  valid_q$8$q;
    reg  valid_q$8$clock;
    reg  valid_q$9$d;
    wire  valid_q$9$q;
    reg  valid_q$9$clock;
    reg  valid_q$10$d;
    wire  valid_q$10$q;
    reg  valid_q$10$clock;
    reg  valid_q$11$d;
    wire  valid_q$11$q;
    reg  valid_q$11$clock;
    reg  valid_q$12$d;
    wire  valid_q$12$q;
    reg  valid_q$12$clock;
    reg  valid_q$13$d;
    wire  valid_q$13$q;
    reg  valid_q$13$clock;
    reg  valid_q$14$d;
    wire  valid_q$14$q;
    reg  valid_q$14$clock;
    reg  [15:0] specular_q$d;
    wire  [15:0] specular_q$q;
    reg  specular_q$clock;
    reg  lit_r$clock;
    reg  [15:0] lit_r$a;
    reg  [15:0] lit_r$b;
    wire  [15:0] lit_r$y;
    reg  lit_g$clock;
    reg  [15:0] lit_g$a;
    reg  [15:0] lit_g$b;
    wire  [15:0] lit_g$y;
    reg  lit_b$clock;
    reg  [15:0] lit_b$a;
    reg  [15:0] lit_b$b;
    wire  [15:0] lit_b$y;
    reg  [15:0] shaded_q$0$d;
    wire  [15:0] shaded_q$0$q;
    reg  shaded_q$0$clock;
    reg  [15:0] shaded_q$1$d;
    wire  [15:0] shaded_q$1$q;
    reg  shaded_q$1$clock;
    reg  [15:0] shaded_q$2$d;
    wire  [15:0] shaded_q$2$q;
    reg  shaded_q$2$clock;
    reg  mul_r$clock;
    reg  [15:0] mul_r$a;
    reg  [15:0] mul_r$b;
    wire  [15:0] mul_r$y;
    reg  mul_g$clock;
    reg  [15:0] mul_g$a;
    reg  [15:0] mul_g$b;
    wire  [15:0] mul_g$y;
    reg  mul_b$clock;
    reg  [15:0] mul_b$a;
    reg  [15:0] mul_b$b;
    wire  [15:0] mul_b$y;
    reg  [15:0] r_q$d;
    wire  [15:0] r_q$q;
    reg  r_q$clock;
    reg  [15:0] g_q$d;
    wire  [15:0] g_q$q;
    reg  g_q$clock;
    reg  [15:0] b_q$d;
    wire  [15:0] b_q$q;
    reg  b_q$clock;
    reg  [15:0] a_q$d;
    wire  [15:0] a_q$q;
    reg  a_q$clock;
    
    // Local signals
    reg  [11:0] row;
    reg  gate;
    reg  [31:0] mag$0;
    reg  [31:0] mag$1;
    reg  [31:0] mag$2;
    reg  [15:0] alpha;
    reg  [15:0] diffuse;
    reg  [15:0] specular;
    reg  [31:0] sum_r;
    reg  [31:0] sum_g;
    reg  [31:0] sum_b;
    
    // Sub module instances
    top$pipeline$shade$1$lut lut(
        .clock(lut$clock),
        .host_write(lut$host_write),
        .host_address(lut$host_address),
        .host_data(lut$host_data),
        .address(lut$address),
        .data(lut$data)
    );
    top$pipeline$shade$1$normal normal(
        .clock(normal$clock),
        .neg$0(normal$neg$0),
        .neg$1(normal$neg$1),
        .neg$2(normal$neg$2),
        .mag$0(normal$mag$0),
        .mag$1(normal$mag$1),
        .mag$2(normal$mag$2),
        .q_neg$0(normal$q_neg$0),
        .q_neg$1(normal$q_neg$1),
        .q_neg$2(normal$q_neg$2),
        .q_mag$0(normal$q_mag$0),
        .q_mag$1(normal$q_mag$1),
        .q_mag$2(normal$q_mag$2)
    );
    top$pipeline$shade$1$lighting lighting(
        .clock(lighting$clock),
        .host_write(lighting$host_write),
        .host_address(lighting$host_address),
        .host_data(lighting$host_data),
        .q_neg$0(lighting$q_neg$0),
        .q_neg$1(lighting$q_neg$1),
        .q_neg$2(lighting$q_neg$2),
        .q_mag$0(lighting$q_mag$0),
        .q_mag$1(lighting$q_mag$1),
        .q_mag$2(lighting$q_mag$2),
        .diffuse(lighting$diffuse),
        .specular(lighting$specular)
    );
    top$pipeline$shade$1$neg_in$0 neg_in$0(
        .d(neg_in$0$d),
        .q(neg_in$0$q),
        .clock(neg_in$0$clock)
    );
    top$pipeline$shade$1$neg_in$1 neg_in$1(
        .d(neg_in$1$d),
        .q(neg_in$1$q),
        .clock(neg_in$1$clock)
    );
    top$pipeline$shade$1$neg_in$2 neg_in$2(
        .d(neg_in$2$d),
        .q(neg_in$2$q),
        .clock(neg_in$2$clock)
    );
    top$pipeline$shade$1$mag_in$0 mag_in$0(
        .d(mag_in$0$d),
        .q(mag_in$0$q),
        .clock(mag_in$0$clock)
    );
    top$pipeline$shade$1$mag_in$1 mag_in$1(
        .d(mag_in$1$d),
        .q(mag_in$1$q),
        .clock(mag_in$1$clock)
    );
    top$pipeline$shade$1$mag_in$2 mag_in$2(
        .d(mag_in$2$d),
        .q(mag_in$2$q),
        .clock(mag_in$2$clock)
    );
    top$pipeline$shade$1$row_q$0 row_q$0(
        .d(row_q$0$d),
        .q(row_q$0$q),
        .clock(row_q$0$clock)
    );
    top$pipeline$shade$1$row_q$1 row_q$1(
        .d(row_q$1$d),
        .q(row_q$1$q),
        .clock(row_q$1$clock)
    );
    top$pipeline$shade$1$row_q$2 row_q$2(
        .d(row_q$2$d),
        .q(row_q$2$q),
        .clock(row_q$2$clock)
    );
    top$pipeline$shade$1$row_q$3 row_q$3(
        .d(row_q$3$d),
        .q(row_q$3$q),
        .clock(row_q$3$clock)
    );
    top$pipeline$shade$1$lut_q$0 lut_q$0(
        .d(lut_q$0$d),
        .q(lut_q$0$q),
        .clock(lut_q$0$clock)
    );
    top$pipeline$shade$1$lut_q$1 lut_q$1(
        .d(lut_q$1$d),
        .q(lut_q$1$q),
        .clock(lut_q$1$clock)
    );
    top$pipeline$shade$1$lut_q$2 lut_q$2(
        .d(lut_q$2$d),
        .q(lut_q$2$q),
        .clock(lut_q$2$clock)
    );
    top$pipeline$shade$1$lut_q$3 lut_q$3(
        .d(lut_q$3$d),
        .q(lut_q$3$q),
        .clock(lut_q$3$clock)
    );
    top$pipeline$shade$1$lut_q$4 lut_q$4(
        .d(lut_q$4$d),
        .q(lut_q$4$q),
        .clock(lut_q$4$clock)
    );
    top$pipeline$shade$1$lut_q$5 lut_q$5(
        .d(lut_q$5$d),
        .q(lut_q$5$q),
        .clock(lut_q$5$clock)
    );
    top$pipeline$shade$1$lut_q$6 lut_q$6(
        .d(lut_q$6$d),
        .q(lut_q$6$q),
        .clock(lut_q$6$clock)
    );
    top$pipeline$shade$1$lut_q$7 lut_q$7(
        .d(lut_q$7$d),
        .q(lut_q$7$q),
        .clock(lut_q$7$clock)
    );
    top$pipeline$shade$1$lut_q$8 lut_q$8(
        .d(lut_q$8$d),
        .q(lut_q$8$q),
        .clock(lut_q$8$clock)
    );
    top$pipeline$shade$1$gate_q$0 gate_q$0(
        .d(gate_q$0$d),
        .q(gate_q$0$q),
        .clock(gate_q$0$clock)
    );
    top$pipeline$shade$1$gate_q$1 gate_q$1(
        .d(gate_q$1$d),
        .q(gate_q$1$q),
        .clock(gate_q$1$clock)
    );
    top$pipeline$shade$1$gate_q$2 gate_q$2(
        .d(gate_q$2$d),
        .q(gate_q$2$q),
        .clock(gate_q$2$clock)
    );
    top$pipeline$shade$1$gate_q$3 gate_q$3(
        .d(gate_q$3$d),
        .q(gate_q$3$q),
        .clock(gate_q$3$clock)
    );
    top$pipeline$shade$1$gate_q$4 gate_q$4(
        .d(gate_q$4$d),
        .q(gate_q$4$q),
        .clock(gate_q$4$clock)
    );
    top$pipeline$shade$1$alpha_q$0 alpha_q$0(
        .d(alpha_q$0$d),
        .q(alpha_q$0$q),
        .clock(alpha_q$0$clock)
    );
    top$pipeline$shade$1$alpha_q$1 alpha_q$1(
        .d(alpha_q$1$d),
        .q(alpha_q$1$q),
        .clock(alpha_q$1$clock)
    );
    top$pipeline$shade$1$alpha_q$2 alpha_q$2(
        .d(alpha_q$2$d),
        .q(alpha_q$2$q),
        .clock(alpha_q$2$clock)
    );
    top$pipeline$shade$1$alpha_q$3 alpha_q$3(
        .d(alpha_q$3$d),
        .q(alpha_q$3$q),
        .clock(alpha_q$3$clock)
    );
    top$pipeline$shade$1$alpha_q$4 alpha_q$4(
        .d(alpha_q$4$d),
        .q(alpha_q$4$q),
        .clock(alpha_q$4$clock)
    );
    top$pipeline$shade$1$alpha_q$5 alpha_q$5(
        .d(alpha_q$5$d),
        .q(alpha_q$5$q),
        .clock(alpha_q$5$clock)
    );
    top$pipeline$shade$1$alpha_q$6 alpha_q$6(
        .d(alpha_q$6$d),
        .q(alpha_q$6$q),
        .clock(alpha_q$6$clock)
    );
    top$pipeline$shade$1$alpha_q$7 alpha_q$7(
        .d(alpha_q$7$d),
        .q(alpha_q$7$q),
        .clock(alpha_q$7$clock)
    );
    top$pipeline$shade$1$alpha_q$8 alpha_q$8(
        .d(alpha_q$8$d),
        .q(alpha_q$8$q),
        .clock(alpha_q$8$clock)
    );
    top$pipeline$shade$1$value_q$0 value_q$0(
        .d(value_q$0$d),
        .q(value_q$0$q),
        .clock(value_q$0$clock)
    );
    top$pipeline$shade$1$value_q$1 value_q$1(
        .d(value_q$1$d),
        .q(value_q$1$q),
        .clock(value_q$1$clock)
    );
    top$pipeline$shade$1$value_q$2 value_q$2(
        .d(value_q$2$d),
        .q(value_q$2$q),
        .clock(value_q$2$clock)
    );
    top$pipeline$shade$1$value_q$3 value_q$3(
        .d(value_q$3$d),
        .q(value_q$3$q),
        .clock(value_q$3$clock)
    );
    top$pipeline$shade$1$value_q$4 value_q$4(
        .d(value_q$4$d),
        .q(value_q$4$q),
        .clock(value_q$4$clock)
    );
    top$pipeline$shade$1$value_q$5 value_q$5(
        .d(value_q$5$d),
        .q(value_q$5$q),
        .clock(value_q$5$clock)
    );
    top$pipeline$shade$1$value_q$6 value_q$6(
        .d(value_q$6$d),
        .q(value_q$6$q),
        .clock(value_q$6$clock)
    );
    top$pipeline$shade$1$value_q$7 value_q$7(
        .d(value_q$7$d),
        .q(value_q$7$q),
        .clock(value_q$7$clock)
    );
    top$pipeline$shade$1$value_q$8 value_q$8(
        .d(value_q$8$d),
        .q(value_q$8$q),
        .clock(value_q$8$clock)
    );
    top$pipeline$shade$1$value_q$9 value_q$9(
        .d(value_q$9$d),
        .q(value_q$9$q),
        .clock(value_q$9$clock)
    );
    top$pipeline$shade$1$value_q$10 value_q$10(
        .d(value_q$10$d),
        .q(value_q$10$q),
        .clock(value_q$10$clock)
    );
    top$pipeline$shade$1$value_q$11 value_q$11(
        .d(value_q$11$d),
        .q(value_q$11$q),
        .clock(value_q$11$clock)
    );
    top$pipeline$shade$1$value_q$12 value_q$12(
        .d(value_q$12$d),
        .q(value_q$12$q),
        .clock(value_q$12$clock)
    );
    top$pipeline$shade$1$value_q$13 value_q$13(
        .d(value_q$13$d),
        .q(value_q$13$q),
        .clock(value_q$13$clock)
    );
    top$pipeline$shade$1$valid_q$0 valid_q$0(
        .d(valid_q$0$d),
        .q(valid_q$0$q),
        .clock(valid_q$0$clock)
    );
    top$pipeline$shade$1$valid_q$1 valid_q$1(
        .d(valid_q$1$d),
        .q(valid_q$1$q),
        .clock(valid_q$1$clock)
    );
    top$pipeline$shade$1$valid_q$2 valid_q$2(
        .d(valid_q$2$d),
        .q(valid_q$2$q),
        .clock(valid_q$2$clock)
    );
    top$pipeline$shade$1$valid_q$3 valid_q$3(
        .d(valid_q$3$d),
        .q(valid_q$3$q),
        .clock(valid_q$3$clock)
    );
    top$pipeline$shade$1$valid_q$4 valid_q$4(
        .d(valid_q$4$d),
        .q(valid_q$4$q),
        .clock(valid_q$4$clock)
    );
    top$pipeline$shade$1$valid_q$5 valid_q$5(
        .d(valid_q$5$d),
        .q(valid_q$5$q),
        .clock(valid_q$5$clock)
    );
    top$pipeline$shade$1$valid_q$6 valid_q$6(
        .d(valid_q$6$d),
        .q(valid_q$6$q),
        .clock(valid_q$6$clock)
    );
    top$pipeline$shade$1$valid_q$7 valid_q$7(
        .d(valid_q$7$d),
        .q(valid_q$7$q),
        .clock(valid_q$7$clock)
    );
    top$pipeline$shade$1$valid_q$8 valid_q$8(
        .d(valid_q$8$d),
        .q(valid_q$8$q),
        .clock(valid_q$8$clock)
    );
    top$pipeline$shade$1$valid_q$9 valid_q$9(
        .d(valid_q$9$d),
        .q(valid_q$9$q),
        .clock(valid_q$9$clock)
    );
    top$pipeline$shade$1$valid_q$10 valid_q$10(
        .d(valid_q$10$d),
        .q(valid_q$10$q),
        .clock(valid_q$10$clock)
    );
    top$pipeline$shade$1$valid_q$11 valid_q$11(
        .d(valid_q$11$d),
        .q(valid_q$11$q),
        .clock(valid_q$11$clock)
    );
    top$pipeline$shade$1$valid_q$12 valid_q$12(
        .d(valid_q$12$d),
        .q(valid_q$12$q),
        .clock(valid_q$12$clock)
    );
    top$pipeline$shade$1$valid_q$13 valid_q$13(
        .d(valid_q$13$d),
        .q(valid_q$13$q),
        .clock(valid_q$13$clock)
    );
    top$pipeline$shade$1$valid_q$14 valid_q$14(
        .d(valid_q$14$d),
        .q(valid_q$14$q),
        .clock(valid_q$14$clock)
    );
    top$pipeline$shade$1$specular_q specular_q(
        .d(specular_q$d),
        .q(specular_q$q),
        .clock(specular_q$clock)
    );
    top$pipeline$shade$1$lit_r lit_r(
        .clock(lit_r$clock),
        .a(lit_r$a),
        .b(lit_r$b),
        .y(lit_r$y)
    );
    top$pipeline$shade$1$lit_g lit_g(
        .clock(lit_g$clock),
        .a(lit_g$a),
        .b(lit_g$b),
        .y(lit_g$y)
    );
    top$pipeline$shade$1$lit_b lit_b(
        .clock(lit_b$clock),
        .a(lit_b$a),
        .b(lit_b$b),
        .y(lit_b$y)
    );
    top$pipeline$shade$1$shaded_q$0 shaded_q$0(
        .d(shaded_q$0$d),
        .q(shaded_q$0$q),
        .clock(shaded_q$0$clock)
    );
    top$pipeline$shade$1$shaded_q$1 shaded_q$1(
        .d(shaded_q$1$d),
        .q(shaded_q$1$q),
        .clock(shaded_q$1$clock)
    );
    top$pipeline$shade$1$shaded_q$2 shaded_q$2(
        .d(shaded_q$2$d),
        .q(shaded_q$2$q),
        .clock(shaded_q$2$clock)
    );
    top$pipeline$shade$1$mul_r mul_r(
        .clock(mul_r$clock),
        .a(mul_r$a),
        .b(mul_r$b),
        .y(mul_r$y)
    );
    top$pipeline$shade$1$mul_g mul_g(
        .clock(mul_g$clock),
        .a(mul_g$a),
        .b(mul_g$b),
        .y(mul_g$y)
    );
    top$pipeline$shade$1$mul_b mul_b(
        .clock(mul_b$clock),
        .a(mul_b$a),
        .b(mul_b$b),
        .y(mul_b$y)
    );
    top$pipeline$shade$1$r_q r_q(
        .d(r_q$d),
        .q(r_q$q),
        .clock(r_q$clock)
    );
    top$pipeline$shade$1$g_q g_q(
        .d(g_q$d),
        .q(g_q$q),
        .clock(g_q$clock)
    );
    top$pipeline$shade$1$b_q b_q(
        .d(b_q$d),
        .q(b_q$q),
        .clock(b_q$clock)
    );
    top$pipeline$shade$1$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    
    // Update code
    reg  [31:0] r_pass;
    reg  [15:0] g_pass;
    reg  [15:0] b_pass;
    reg  [15:0] a_pass;
    reg  valid_pass;
    always @(*) begin
        specular_q$clock = clock;
        r_q$clock = clock;
        g_q$clock = clock;
        b_q$clock = clock;
        a_q$clock = clock;
        specular_q$d = specular_q$q;
        r_q$d = r_q$q;
        g_q$d = g_q$q;
        b_q$d = b_q$q;
        a_q$d = a_q$q;
        lut$clock = clock;
        lut$host_write = host_write;
        lut$host_address = host_address;
        lut$host_data = host_data;
        alpha_gm$clock = clock;
        alpha_gm$host_write = host_write;
        alpha_gm$host_address = host_address;
        alpha_gm$host_data = host_data;
        gm_bin$clock = clock;
        gm_bin$host_write = host_write;
        gm_bin$host_address = host_address;
        gm_bin$host_data = host_data;
        lighting$clock = clock;
        lighting$host_write = host_write;
        lighting$host_address = host_address;
        lighting$host_data = host_data;
        normal$clock = clock;
        lit_r$clock = clock;
        lit_g$clock = clock;
        lit_b$clock = clock;
        mul_r$clock = clock;
        mul_g$clock = clock;
        mul_b$clock = clock;
        gate = invalid | (edge_transparent & at_edge);
        row = 12'(value >> shift);
        mag$0 = gx_mag;
        mag$1 = gy_mag;
        mag$2 = gz_mag;
        if (gate) begin
            row = 'h0;
            mag$0 = 'h0;
            mag$1 = 'h0;
            mag$2 = 'h0;
        end
        neg_in$0$clock = clock;
        mag_in$0$clock = clock;
        mag_in$0$d = mag$0;
        neg_in$1$clock = clock;
        mag_in$1$clock = clock;
        mag_in$1$d = mag$1;
        neg_in$2$clock = clock;
        mag_in$2$clock = clock;
        mag_in$2$d = mag$2;
        neg_in$0$d = gx_neg & ~gate;
        neg_in$1$d = gy_neg & ~gate;
        neg_in$2$d = gz_neg & ~gate;
        lut$address = row_q$0$q;
        normal$neg$0 = neg_in$0$q;
        normal$mag$0 = mag_in$0$q;
        gm_bin$mag$0 = mag_in$0$q;
        lighting$q_neg$0 = normal$q_neg$0;
        lighting$q_mag$0 = normal$q_mag$0;
        normal$neg$1 = neg_in$1$q;
        normal$mag$1 = mag_in$1$q;
        gm_bin$mag$1 = mag_in$1$q;
        lighting$q_neg$1 = normal$q_neg$1;
        lighting$q_mag$1 = normal$q_mag$1;
        normal$neg$2 = neg_in$2$q;
        normal$mag$2 = mag_in$2$q;
        gm_bin$mag$2 = mag_in$2$q;
        lighting$q_neg$2 = normal$q_neg$2;
        lighting$q_mag$2 = normal$q_mag$2;
        row_q$0$clock = clock;
        row_q$1$clock = clock;
        row_q$2$clock = clock;
        row_q$3$clock = clock;
        row_q$0$d = row;
        row_q$1$d = row_q$0$q;
        row_q$2$d = row_q$1$q;
        row_q$3$d = row_q$2$q;
        lut_q$0$clock = clock;
        alpha_q$0$clock = clock;
        lut_q$1$clock = clock;
        alpha_q$1$clock = clock;
        lut_q$2$clock = clock;
        alpha_q$2$clock = clock;
        lut_q$3$clock = clock;
        alpha_q$3$clock = clock;
        lut_q$4$clock = clock;
        alpha_q$4$clock = clock;
        lut_q$5$clock = clock;
        alpha_q$5$clock = clock;
        lut_q$6$clock = clock;
        alpha_q$6$clock = clock;
        lut_q$7$clock = clock;
        alpha_q$7$clock = clock;
        lut_q$8$clock = clock;
        alpha_q$8$clock = clock;
        lut_q$0$d = lut$data;
        lut_q$1$d = lut_q$0$q;
        lut_q$2$d = lut_q$1$q;
        lut_q$3$d = lut_q$2$q;
        lut_q$4$d = lut_q$3$q;
        lut_q$5$d = lut_q$4$q;
        lut_q$6$d = lut_q$5$q;
        lut_q$7$d = lut_q$6$q;
        lut_q$8$d = lut_q$7$q;
        gate_q$0$clock = clock;
        gate_q$1$clock = clock;
        gate_q$2$clock = clock;
        gate_q$3$clock = clock;
        gate_q$4$clock = clock;
        gate_q$0$d = gate;
        gate_q$1$d = gate_q$0$q;
        gate_q$2$d = gate_q$1$q;
        gate_q$3$d = gate_q$2$q;
        gate_q$4$d = gate_q$3$q;
        value_q$0$clock = clock;
        value_q$1$clock = clock;
        value_q$2$clock = clock;
        value_q$3$clock = clock;
        value_q$4$clock = clock;
        value_q$5$clock = clock;
        value_q$6$clock = clock;
        value_q$7$clock = clock;
        value_q$8$clock = clock;
        value_q$9$clock = clock;
        value_q$10$clock = clock;
        value_q$11$clock = clock;
        value_q$12$clock = clock;
        value_q$13$clock = clock;
        valid_q$0$clock = clock;
        valid_q$1$clock = clock;
        valid_q$2$clock = clock;
        valid_q$3$clock = clock;
        valid_q$4$clock = clock;
        valid_q$5$clock = clock;
        valid_q$6$clock = clock;
        valid_q$7$clock = clock;
        valid_q$8$clock = clock;
        valid_q$9$clock = clock;
        valid_q$10$clock = clock;
        valid_q$11$clock = clock;
        valid_q$12$clock = clock;
        valid_q$13$clock = clock;
        valid_q$14$clock = clock;
        value_q$0$d = value;
        valid_q$0$d = ~invalid | xray;
        value_q$1$d = value_q$0$q;
        value_q$2$d = value_q$1$q;
        value_q$3$d = value_q$2$q;
        value_q$4$d = value_q$3$q;
        value_q$5$d = value_q$4$q;
        value_q$6$d = value_q$5$q;
        value_q$7$d = value_q$6$q;
        value_q$8$d = value_q$7$q;
        value_q$9$d = value_q$8$q;
        value_q$10$d = value_q$9$q;
        value_q$11$d = value_q$10$q;
        value_q$12$d = value_q$11$q;
        value_q$13$d = value_q$12$q;
        valid_q$1$d = valid_q$0$q;
        valid_q$2$d = valid_q$1$q;
        valid_q$3$d = valid_q$2$q;
        valid_q$4$d = valid_q$3$q;
        valid_q$5$d = valid_q$4$q;
        valid_q$6$d = valid_q$5$q;
        valid_q$7$d = valid_q$6$q;
        valid_q$8$d = valid_q$7$q;
        valid_q$9$d = valid_q$8$q;
        valid_q$10$d = valid_q$9$q;
        valid_q$11$d = valid_q$10$q;
        valid_q$12$d = valid_q$11$q;
        valid_q$13$d = valid_q$12$q;
        valid_q$14$d = valid_q$13$q;
        alpha_gm$address = (16'(row_q$3$q) << 'h4) | 16'(gm_bin$bin);
        alpha = 16'(lut_q$2$q >> 'h30);
        if (gm_on) begin
            alpha = alpha_gm$data;
        end
        if (gate_q$4$q) begin
            alpha = 'h0;
        end
        alpha_q$0$d = alpha;
        alpha_q$1$d = alpha_q$0$q;
        alpha_q$2$d = alpha_q$1$q;
        alpha_q$3$d = alpha_q$2$q;
        alpha_q$4$d = alpha_q$3$q;
        alpha_q$5$d = alpha_q$4$q;
        alpha_q$6$d = alpha_q$5$q;
        alpha_q$7$d = alpha_q$6$q;
        alpha_q$8$d = alpha_q$7$q;
        diffuse = m_max;
        specular = 'h0;
        if (shaded) begin
            diffuse = lighting$diffuse;
            specular = lighting$specular;
        end
        specular_q$d = specular;
        lit_r$a = 16'(lut_q$8$q);
        lit_g$a = 16'(lut_q$8$q >> 'h10);
        lit_b$a = 16'(lut_q$8$q >> 'h20);
        lit_r$b = diffuse;
        lit_g$b = diffuse;
        lit_b$b = diffuse;
        sum_r = 32'(lit_r$y) + 32'(specular_q$q);
        sum_g = 32'(lit_g$y) + 32'(specular_q$q);
        sum_b = 32'(lit_b$y) + 32'(specular_q$q);
        shaded_q$0$clock = clock;
        shaded_q$1$clock = clock;
        shaded_q$2$clock = clock;
        shaded_q$0$d = 16'(sum_r);
        if (sum_r > 32'(m_max)) begin
            shaded_q$0$d = m_max;
        end
        shaded_q$1$d = 16'(sum_g);
        if (sum_g > 32'(m_max)) begin
            shaded_q$1$d = m_max;
        end
        shaded_q$2$d = 16'(sum_b);
        if (sum_b > 32'(m_max)) begin
            shaded_q$2$d = m_max;
        end
        mul_r$a = shaded_q$0$q;
        mul_g$a = shaded_q$1$q;
        mul_b$a = shaded_q$2$q;
        mul_r$b = alpha_q$7$q;
        mul_g$b = alpha_q$7$q;
        mul_b$b = alpha_q$7$q;
        if (scalar) begin
            r_q$d = value_q$13$q;
            g_q$d = 'h0;
            b_q$d = 'h0;
            a_q$d = 'h0;
        end
        else if (xray) begin
            r_q$d = alpha_q$8$q;
            g_q$d = 'h0;
            b_q$d = 'h0;
            a_q$d = 'h0;
        end
        else begin
            r_q$d = mul_r$y;
            g_q$d = mul_g$y;
            b_q$d = mul_b$y;
            a_q$d = alpha_q$8$q;
        end
        r_pass = 'h0;
        g_pass = 'h0;
        b_pass = 'h0;
        a_pass = 'h0;
        valid_pass = 1'b0;
        if (enabled) begin
            r_pass = 32'(r_q$q);
            g_pass = g_q$q;
            b_pass = b_q$q;
            a_pass = a_q$q;
            valid_pass = valid_q$14$q;
        end
        r = r_pass;
        g = g_pass;
        b = b_pass;
        a = a_pass;
        valid = valid_pass;
    end
    
endmodule // top$pipeline$shade$1
module top$pipeline$shade$1$a_q(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$a_q
module top$pipeline$shade$1$alpha_q$0(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$alpha_q$0
module top$pipeline$shade$1$alpha_q$1(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$alpha_q$1
module top$pipeline$shade$1$alpha_q$2(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$alpha_q$2
module top$pipeline$shade$1$alpha_q$3(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$alpha_q$3
module top$pipeline$shade$1$alpha_q$4(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$alpha_q$4
module top$pipeline$shade$1$alpha_q$5(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$alpha_q$5
module top$pipeline$shade$1$alpha_q$6(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$alpha_q$6
module top$pipeline$shade$1$alpha_q$7(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$alpha_q$7
module top$pipeline$shade$1$alpha_q$8(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$alpha_q$8
module top$pipeline$shade$1$b_q(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$b_q
module top$pipeline$shade$1$g_q(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$g_q
module top$pipeline$shade$1$gate_q$0(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$gate_q$0
module top$pipeline$shade$1$gate_q$1(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$gate_q$1
module top$pipeline$shade$1$gate_q$2(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$gate_q$2
module top$pipeline$shade$1$gate_q$3(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$gate_q$3
module top$pipeline$shade$1$gate_q$4(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$gate_q$4
module top$pipeline$shade$1$lighting(clock,host_write,host_address,host_data,q_neg$0,q_neg$1,q_neg$2,q_mag$0,q_mag$1,q_mag$2,diffuse,specular);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  q_neg$0;
    input wire  q_neg$1;
    input wire  q_neg$2;
    input wire  [3:0] q_mag$0;
    input wire  [3:0] q_mag$1;
    input wire  [3:0] q_mag$2;
    output reg  [15:0] diffuse;
    output reg  [15:0] specular;
    
    // Constant declarations
    localparam  half_ulp = 64'h2000000;
    localparam  shift = 8'h1a;
    localparam  last = 64'h3ff;
    
    // Stub signals
    reg  regs$clock;
    reg  regs$host_write;
    reg  [23:0] regs$host_address;
    reg  [63:0] regs$host_data;
    wire  [63:0] regs$q$0;
    wire  [63:0] regs$q$1;
    reg  [9:0] rnorm$address;
    wire  [15:0] rnorm$data;
    reg  [3:0] square$0$address;
    wire  [7:0] square$0$data;
    reg  [3:0] square$1$address;
    wire  [7:0] square$1$data;
    reg  [3:0] square$2$address;
    wire  [7:0] square$2$data;
    reg  diffuse_table$clock;
    reg  diffuse_table$host_write;
    reg  [23:0] diffuse_table$host_address;
    reg  [63:0] diffuse_table$host_data;
    reg  [9:0] diffuse_table$address;
    wire  [15:0] diffuse_table$data;
    reg  specular_table$clock;
    reg  specular_table$host_write;
    reg  [23:0] specular_table$host_address;
    reg  [63:0] specular_table$host_data;
    reg  [9:0] specular_table$address;
    wire  [15:0] specular_table$data;
    reg  [15:0] ml_q$0$d;
    wire  [15:0] ml_q$0$q;
    reg  ml_q$0$clock;
    reg  [15:0] ml_q$1$d;
    wire  [15:0] ml_q$1$q;
    reg  ml_q$1$clock;
    reg  [15:0] ml_q$2$d;
    wire  [15:0] ml_q$2$q;
    reg  ml_q$2$clock;
    reg  [15:0] mh_q$0$d;
    wire  [15:0] mh_q$0$q;
    reg  mh_q$0$clock;
    reg  [15:0] mh_q$1$d;
    wire  [15:0] mh_q$1$q;
    reg  mh_q$1$clock;
    reg  [15:0] mh_q$2$d;
    wire  [15:0] mh_q$2$q;
    reg  mh_q$2$clock;
    reg  [31:0] p_l$0$d;
    wire  [31:0] p_l$0$q;
    reg  p_l$0$clock;
    reg  [31:0] p_l$1$d;
    wire  [31:0] p_l$1$q;
    reg  p_l$1$clock;
    reg  [31:0] p_l$2$d;
    wire  [31:0] p_l$2$q;
    reg  p_l$2$clock;
    reg  [31:0] p_h$0$d;
    wire  [31:0] p_h$0$q;
    reg  p_h$0$clock;
    reg  [31:0] p_h$1$d;
    wire  [31:0] p_h$1$q;
    reg  p_h$1$clock;
    reg  [31:0] p_h$2$d;
    wire  [31:0] p_h$2$q;
    reg  p_h$2$clock;
    reg  sl_q$0$d;
    wire  sl_q$0$q;
    reg  sl_q$0$clock;
    reg  sl_q$1$d;
    wire  sl_q$1$q;
    reg  sl_q$1$clock;
    reg  sl_q$2$d;
    wire  sl_q$2$q;
    reg  sl_q$2$clock;
    reg  sh_q$0$d;
    wire  sh_q$0$q;
    reg  sh_q$0$clock;
    reg  sh_q$1$d;
    wire  sh_q$1$q;
    reg  sh_q$1$clock;
    reg  sh_q$2$d;
    wire  sh_q$2$q;
    reg  sh_q$2$clock;
    reg  [15:0] n2_q$d;
    wire  [15:0] n2_q$q;
    reg  n2_q$clock;
    reg  [31:0] dot_l$d;
    wire  [31:0] dot_l$q;
    reg  dot_l$clock;
    reg  [31:0] dot_h$d;
    wire  [31:0] dot_h$q;
    reg  dot_h$clock;
    reg  [15:0] rn$d;
    wire  [15:0] rn$q;
    reg  rn$clock;
    reg  [15:0] d16_l$d;
    wire  [15:0] d16_l$q;
    reg  d16_l$clock;
    reg  [15:0] d16_h$d;
    wire  [15:0] d16_h$q;
    reg  d16_h$clock;
    reg  [15:0] rn_3$d;
    wire  [15:0] rn_3$q;
    reg  rn_3$clock;
    reg  lit_3$d;
    wire  lit_3$q;
    reg  lit_3$clock;
    reg  [31:0] t_l$d;
    wire  [31:0] t_l$q;
    reg  t_l$clock;
    reg  [31:0] t_h$d;
    wire  [31:0] t_h$q;
    reg  t_h$clock;
    reg  lit_4$d;
    wire  lit_4$q;
    reg  lit_4$clock;
    reg  [9:0] idx_l$d;
    wire  [9:0] idx_l$q;
    reg  idx_l$clock;
    reg  [9:0] idx_h$d;
    wire  [9:0] idx_h$q;
    reg  idx_h$clock;
    reg  lit_5$d;
    wire  lit_5$q;
    reg  lit_5$clock;
    reg  lit_6$d;
    wire  lit_6$q;
    reg  lit_6$clock;
    reg  [15:0] diffuse_q$d;
    wire  [15:0] diffuse_q$q;
    reg  diffuse_q$clock;
    reg  [15:0] specular_q$d;
    wire  [15:0] specular_q$q;
    reg  specular_q$clock;
    
    // Local signals
    reg  [15:0] m_l$0;
    reg  [15:0] m_l$1;
    reg  [15:0] m_l$2;
    reg  [15:0] m_h$0;
    reg  [15:0] m_h$1;
    reg  [15:0] m_h$2;
    reg  [15:0] qm$0;
    reg  [15:0] qm$1;
    reg  [15:0] qm$2;
    reg  [31:0] t_pl$0;
    reg  [31:0] t_pl$1;
    reg  [31:0] t_pl$2;
    reg  [31:0] t_ph$0;
    reg  [31:0] t_ph$1;
    reg  [31:0] t_ph$2;
    reg  [15:0] n2;
    reg  [63:0] i_l;
    reg  [63:0] i_h;
    
    // Sub module instances
    top$pipeline$shade$1$lighting$regs regs(
        .clock(regs$clock),
        .host_write(regs$host_write),
        .host_address(regs$host_address),
        .host_data(regs$host_data),
        .q$0(regs$q$0),
        .q$1(regs$q$1)
    );
    top$pipeline$shade$1$lighting$rnorm rnorm(
        .address(rnorm$address),
        .data(rnorm$data)
    );
    top$pipeline$shade$1$lighting$square$0 square$0(
        .address(square$0$address),
        .data(square$0$data)
    );
    top$pipeline$shade$1$lighting$square$1 square$1(
        .address(square$1$address),
        .data(square$1$data)
    );
    top$pipeline$shade$1$lighting$square$2 square$2(
        .address(square$2$address),
        .data(square$2$data)
    );
    top$pipeline$shade$1$lighting$diffuse_table diffuse_table(
        .clock(diffuse_table$clock),
        .host_write(diffuse_table$host_write),
        .host_address(diffuse_table$host_address),
        .host_data(diffuse_table$host_data),
        .address(diffuse_table$address),
        .data(diffuse_table$data)
    );
    top$pipeline$shade$1$lighting$specular_table specular_table(
        .clock(specular_table$clock),
        .host_write(specular_table$host_write),
        .host_address(specular_table$host_address),
        .host_data(specular_table$host_data),
        .address(specular_table$address),
        .data(specular_table$data)
    );
    top$pipeline$shade$1$lighting$ml_q$0 ml_q$0(
        .d(ml_q$0$d),
        .q(ml_q$0$q),
        .clock(ml_q$0$clock)
    );
    top$pipeline$shade$1$lighting$ml_q$1 ml_q$1(
        .d(ml_q$1$d),
        .q(ml_q$1$q),
        .clock(ml_q$1$clock)
    );
    top$pipeline$shade$1$lighting$ml_q$2 ml_q$2(
        .d(ml_q$2$d),
        .q(ml_q$2$q),
        .clock(ml_q$2$clock)
    );
    top$pipeline$shade$1$lighting$mh_q$0 mh_q$0(
        .d(mh_q$0$d),
        .q(mh_q$0$q),
        .clock(mh_q$0$clock)
    );
    top$pipeline$shade$1$lighting$mh_q$1 mh_q$1(
        .d(mh_q$1$d),
        .q(mh_q$1$q),
        .clock(mh_q$1$clock)
    );
    top$pipeline$shade$1$lighting$mh_q$2 mh_q$2(
        .d(mh_q$2$d),
        .q(mh_q$2$q),
        .clock(mh_q$2$clock)
    );
    top$pipeline$shade$1$lighting$p_l$0 p_l$0(
        .d(p_l$0$d),
        .q(p_l$0$q),
        .clock(p_l$0$clock)
    );
    top$pipeline$shade$1$lighting$p_l$1 p_l$1(
        .d(p_l$1$d),
        .q(p_l$1$q),
        .clock(p_l$1$clock)
    );
    top$pipeline$shade$1$lighting$p_l$2 p_l$2(
        .d(p_l$2$d),
        .q(p_l$2$q),
        .clock(p_l$2$clock)
    );
    top$pipeline$shade$1$lighting$p_h$0 p_h$0(
        .d(p_h$0$d),
        .q(p_h$0$q),
        .clock(p_h$0$clock)
    );
    top$pipeline$shade$1$lighting$p_h$1 p_h$1(
        .d(p_h$1$d),
        .q(p_h$1$q),
        .clock(p_h$1$clock)
    );
    top$pipeline$shade$1$lighting$p_h$2 p_h$2(
        .d(p_h$2$d),
        .q(p_h$2$q),
        .clock(p_h$2$clock)
    );
    top$pipeline$shade$1$lighting$sl_q$0 sl_q$0(
        .d(sl_q$0$d),
        .q(sl_q$0$q),
        .clock(sl_q$0$clock)
    );
    top$pipeline$shade$1$lighting$sl_q$1 sl_q$1(
        .d(sl_q$1$d),
        .q(sl_q$1$q),
        .clock(sl_q$1$clock)
    );
    top$pipeline$shade$1$lighting$sl_q$2 sl_q$2(
        .d(sl_q$2$d),
        .q(sl_q$2$q),
        .clock(sl_q$2$clock)
    );
    top$pipeline$shade$1$lighting$sh_q$0 sh_q$0(
        .d(sh_q$0$d),
        .q(sh_q$0$q),
        .clock(sh_q$0$clock)
    );
    top$pipeline$shade$1$lighting$sh_q$1 sh_q$1(
        .d(sh_q$1$d),
        .q(sh_q$1$q),
        .clock(sh_q$1$clock)
    );
    top$pipeline$shade$1$lighting$sh_q$2 sh_q$2(
        .d(sh_q$2$d),
        .q(sh_q$2$q),
        .clock(sh_q$2$clock)
    );
    top$pipeline$shade$1$lighting$n2_q n2_q(
        .d(n2_q$d),
        .q(n2_q$q),
        .clock(n2_q$clock)
    );
    top$pipeline$shade$1$lighting$dot_l dot_l(
        .d(dot_l$d),
        .q(dot_l$q),
        .clock(dot_l$clock)
    );
    top$pipeline$shade$1$lighting$dot_h dot_h(
        .d(dot_h$d),
        .q(dot_h$q),
        .clock(dot_h$clock)
    );
    top$pipeline$shade$1$lighting$rn rn(
        .d(rn$d),
        .q(rn$q),
        .clock(rn$clock)
    );
    top$pipeline$shade$1$lighting$d16_l d16_l(
        .d(d16_l$d),
        .q(d16_l$q),
        .clock(d16_l$clock)
    );
    top$pipeline$shade$1$lighting$d16_h d16_h(
        .d(d16_h$d),
        .q(d16_h$q),
        .clock(d16_h$clock)
    );
    top$pipeline$shade$1$lighting$rn_3 rn_3(
        .d(rn_3$d),
        .q(rn_3$q),
        .clock(rn_3$clock)
    );
    top$pipeline$shade$1$lighting$lit_3 lit_3(
        .d(lit_3$d),
        .q(lit_3$q),
        .clock(lit_3$clock)
    );
    top$pipeline$shade$1$lighting$t_l t_l(
        .d(t_l$d),
        .q(t_l$q),
        .clock(t_l$clock)
    );
    top$pipeline$shade$1$lighting$t_h t_h(
        .d(t_h$d),
        .q(t_h$q),
        .clock(t_h$clock)
    );
    top$pipeline$shade$1$lighting$lit_4 lit_4(
        .d(lit_4$d),
        .q(lit_4$q),
        .clock(lit_4$clock)
    );
    top$pipeline$shade$1$lighting$idx_l idx_l(
        .d(idx_l$d),
        .q(idx_l$q),
        .clock(idx_l$clock)
    );
    top$pipeline$shade$1$lighting$idx_h idx_h(
        .d(idx_h$d),
        .q(idx_h$q),
        .clock(idx_h$clock)
    );
    top$pipeline$shade$1$lighting$lit_5 lit_5(
        .d(lit_5$d),
        .q(lit_5$q),
        .clock(lit_5$clock)
    );
    top$pipeline$shade$1$lighting$lit_6 lit_6(
        .d(lit_6$d),
        .q(lit_6$q),
        .clock(lit_6$clock)
    );
    top$pipeline$shade$1$lighting$diffuse_q diffuse_q(
        .d(diffuse_q$d),
        .q(diffuse_q$q),
        .clock(diffuse_q$clock)
    );
    top$pipeline$shade$1$lighting$specular_q specular_q(
        .d(specular_q$d),
        .q(specular_q$q),
        .clock(specular_q$clock)
    );
    
    // Update code
    always @(*) begin
        n2_q$clock = clock;
        dot_l$clock = clock;
        dot_h$clock = clock;
        rn$clock = clock;
        d16_l$clock = clock;
        d16_h$clock = clock;
        rn_3$clock = clock;
        lit_3$clock = clock;
        t_l$clock = clock;
        t_h$clock = clock;
        lit_4$clock = clock;
        idx_l$clock = clock;
        idx_h$clock = clock;
        lit_5$clock = clock;
        lit_6$clock = clock;
        diffuse_q$clock = clock;
        specular_q$clock = clock;
        n2_q$d = n2_q$q;
        dot_l$d = dot_l$q;
        dot_h$d = dot_h$q;
        rn$d = rn$q;
        d16_l$d = d16_l$q;
        d16_h$d = d16_h$q;
        rn_3$d = rn_3$q;
        lit_3$d = lit_3$q;
        t_l$d = t_l$q;
        t_h$d = t_h$q;
        lit_4$d = lit_4$q;
        idx_l$d = idx_l$q;
        idx_h$d = idx_h$q;
        lit_5$d = lit_5$q;
        lit_6$d = lit_6$q;
        diffuse_q$d = diffuse_q$q;
        specular_q$d = specular_q$q;
        regs$clock = clock;
        regs$host_write = host_write;
        regs$host_address = host_address;
        regs$host_data = host_data;
        diffuse_table$clock = clock;
        diffuse_table$host_write = host_write;
        diffuse_table$host_address = host_address;
        diffuse_table$host_data = host_data;
        specular_table$clock = clock;
        specular_table$host_write = host_write;
        specular_table$host_address = host_address;
        specular_table$host_data = host_data;
        qm$0 = 16'(q_mag$0);
        qm$1 = 16'(q_mag$1);
        qm$2 = 16'(q_mag$2);
        m_l$0 = regs$q$0[('h0)+:(16)];
        if (regs$q$0['hf]) begin
            m_l$0 = 'h0 - regs$q$0[('h0)+:(16)];
        end
        m_l$1 = regs$q$0[('h10)+:(16)];
        if (regs$q$0['h1f]) begin
            m_l$1 = 'h0 - regs$q$0[('h10)+:(16)];
        end
        m_l$2 = regs$q$0[('h20)+:(16)];
        if (regs$q$0['h2f]) begin
            m_l$2 = 'h0 - regs$q$0[('h20)+:(16)];
        end
        m_h$0 = regs$q$1[('h0)+:(16)];
        if (regs$q$1['hf]) begin
            m_h$0 = 'h0 - regs$q$1[('h0)+:(16)];
        end
        m_h$1 = regs$q$1[('h10)+:(16)];
        if (regs$q$1['h1f]) begin
            m_h$1 = 'h0 - regs$q$1[('h10)+:(16)];
        end
        m_h$2 = regs$q$1[('h20)+:(16)];
        if (regs$q$1['h2f]) begin
            m_h$2 = 'h0 - regs$q$1[('h20)+:(16)];
        end
        ml_q$0$clock = clock;
        mh_q$0$clock = clock;
        sl_q$0$clock = clock;
        sh_q$0$clock = clock;
        p_l$0$clock = clock;
        p_h$0$clock = clock;
        square$0$address = q_mag$0;
        ml_q$0$d = m_l$0;
        mh_q$0$d = m_h$0;
        p_l$0$d = qm$0 * ml_q$0$q;
        p_h$0$d = qm$0 * mh_q$0$q;
        ml_q$1$clock = clock;
        mh_q$1$clock = clock;
        sl_q$1$clock = clock;
        sh_q$1$clock = clock;
        p_l$1$clock = clock;
        p_h$1$clock = clock;
        square$1$address = q_mag$1;
        ml_q$1$d = m_l$1;
        mh_q$1$d = m_h$1;
        p_l$1$d = qm$1 * ml_q$1$q;
        p_h$1$d = qm$1 * mh_q$1$q;
        ml_q$2$clock = clock;
        mh_q$2$clock = clock;
        sl_q$2$clock = clock;
        sh_q$2$clock = clock;
        p_l$2$clock = clock;
        p_h$2$clock = clock;
        square$2$address = q_mag$2;
        ml_q$2$d = m_l$2;
        mh_q$2$d = m_h$2;
        p_l$2$d = qm$2 * ml_q$2$q;
        p_h$2$d = qm$2 * mh_q$2$q;
        sl_q$0$d = q_neg$0 ^ regs$q$0['hf];
        sl_q$1$d = q_neg$1 ^ regs$q$0['h1f];
        sl_q$2$d = q_neg$2 ^ regs$q$0['h2f];
        sh_q$0$d = q_neg$0 ^ regs$q$1['hf];
        sh_q$1$d = q_neg$1 ^ regs$q$1['h1f];
        sh_q$2$d = q_neg$2 ^ regs$q$1['h2f];
        n2 = 16'(square$0$data) + 16'(square$1$data) + 16'(square$2$data);
        n2_q$d = n2;
        t_pl$0 = p_l$0$q;
        if (sl_q$0$q) begin
            t_pl$0 = 'h0 - p_l$0$q;
        end
        t_ph$0 = p_h$0$q;
        if (sh_q$0$q) begin
            t_ph$0 = 'h0 - p_h$0$q;
        end
        t_pl$1 = p_l$1$q;
        if (sl_q$1$q) begin
            t_pl$1 = 'h0 - p_l$1$q;
        end
        t_ph$1 = p_h$1$q;
        if (sh_q$1$q) begin
            t_ph$1 = 'h0 - p_h$1$q;
        end
        t_pl$2 = p_l$2$q;
        if (sl_q$2$q) begin
            t_pl$2 = 'h0 - p_l$2$q;
        end
        t_ph$2 = p_h$2$q;
        if (sh_q$2$q) begin
            t_ph$2 = 'h0 - p_h$2$q;
        end
        dot_l$d = t_pl$0 + t_pl$1 + t_pl$2;
        dot_h$d = t_ph$0 + t_ph$1 + t_ph$2;
        rnorm$address = 10'(n2_q$q);
        rn$d = rnorm$data;
        d16_l$d = dot_l$q[('h0)+:(16)];
        if (dot_l$q['h1f] | (dot_l$q == 'h0)) begin
            d16_l$d = 'h0;
        end
        else if (dot_l$q > 'hffff) begin
            d16_l$d = 'hffff;
        end
        d16_h$d = dot_h$q[('h0)+:(16)];
        if (dot_h$q['h1f] | (dot_h$q == 'h0)) begin
            d16_h$d = 'h0;
        end
        else if (dot_h$q > 'hffff) begin
            d16_h$d = 'hffff;
        end
        rn_3$d = rn$q;
        lit_3$d = ~dot_l$q['h1f] & (dot_l$q != 'h0);
        t_l$d = d16_l$q * rn_3$q;
        t_h$d = d16_h$q * rn_3$q;
        lit_4$d = lit_3$q;
        i_l = ((64'(t_l$q) << 'ha) - 64'(t_l$q) + half_ulp) >> shift;
        if (i_l > last) begin
            i_l = last;
        end
        i_h = ((64'(t_h$q) << 'ha) - 64'(t_h$q) + half_ulp) >> shift;
        if (i_h > last) begin
            i_h = last;
        end
        idx_l$d = 10'(i_l);
        idx_h$d = 10'(i_h);
        lit_5$d = lit_4$q;
        diffuse_table$address = idx_l$q;
        specular_table$address = idx_h$q;
        lit_6$d = lit_5$q;
        diffuse_q$d = diffuse_table$data;
        specular_q$d = 'h0;
        if (lit_6$q) begin
            specular_q$d = specular_table$data;
        end
        diffuse = diffuse_q$q;
        specular = specular_q$q;
    end
    
endmodule // top$pipeline$shade$1$lighting
module top$pipeline$shade$1$lighting$d16_h(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$lighting$d16_h
module top$pipeline$shade$1$lighting$d16_l(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$lighting$d16_l
module top$pipeline$shade$1$lighting$diffuse_q(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$lighting$diffuse_q
module top$pipeline$shade$1$lighting$diffuse_table(clock,host_write,host_address,host_data,address,data);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  [9:0] address;
    output reg  [15:0] data;
    
    // Constant declarations
    localparam  base = 24'h30000;
    localparam  window = 24'h30400;
    
    // Stub signals
    reg  [9:0] ram$read_address;
    reg  ram$read_clock;
    wire  [15:0] ram$read_data;
    reg  [9:0] ram$write_address;
    reg  ram$write_clock;
    reg  [15:0] ram$write_data;
    reg  ram$write_enable;
    
    // Sub module instances
    top$pipeline$shade$1$lighting$diffuse_table$ram ram(
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
        ram$write_address = 10'(host_address - base);
        ram$write_data = 16'(host_data);
        ram$read_address = address;
        data = ram$read_data;
    end
    
endmodule // top$pipeline$shade$1$lighting$diffuse_table
module top$pipeline$shade$1$lighting$diffuse_table$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [9:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [9:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[1023:0];
    
    always @(posedge read_clock) begin
       read_data <= {8'd0, mem[read_address[9:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[9:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$pipeline$shade$1$lighting$diffuse_table$ram
module top$pipeline$shade$1$lighting$dot_h(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$lighting$dot_h
module top$pipeline$shade$1$lighting$dot_l(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$lighting$dot_l
module top$pipeline$shade$1$lighting$idx_h(d,q,clock);
    
    // Module arguments
    input wire  [9:0] d;
    output reg  [9:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 10'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$lighting$idx_h
module top$pipeline$shade$1$lighting$idx_l(d,q,clock);
    
    // Module arguments
    input wire  [9:0] d;
    output reg  [9:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 10'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$lighting$idx_l
module top$pipeline$shade$1$lighting$lit_3(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$lighting$lit_3
module top$pipeline$shade$1$lighting$lit_4(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$lighting$lit_4
module top$pipeline$shade$1$lighting$lit_5(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$lighting$lit_5
module top$pipeline$shade$1$lighting$lit_6(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$lighting$lit_6
module top$pipeline$shade$1$lighting$mh_q$0(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$lighting$mh_q$0
module top$pipeline$shade$1$lighting$mh_q$1(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$lighting$mh_q$1
module top$pipeline$shade$1$lighting$mh_q$2(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$lighting$mh_q$2
module top$pipeline$shade$1$lighting$ml_q$0(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$lighting$ml_q$0
module top$pipeline$shade$1$lighting$ml_q$1(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$lighting$ml_q$1
module top$pipeline$shade$1$lighting$ml_q$2(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$lighting$ml_q$2
module top$pipeline$shade$1$lighting$n2_q(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$lighting$n2_q
module top$pipeline$shade$1$lighting$p_h$0(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$lighting$p_h$0
module top$pipeline$shade$1$lighting$p_h$1(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$lighting$p_h$1
module top$pipeline$shade$1$lighting$p_h$2(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$lighting$p_h$2
module top$pipeline$shade$1$lighting$p_l$0(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$lighting$p_l$0
module top$pipeline$shade$1$lighting$p_l$1(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$lighting$p_l$1
module top$pipeline$shade$1$lighting$p_l$2(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$lighting$p_l$2
module top$pipeline$shade$1$lighting$regs(clock,host_write,host_address,host_data,q$0,q$1);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    output reg  [63:0] q$0;
    output reg  [63:0] q$1;
    
    // Constant declarations
    localparam  address$0 = 24'h10;
    localparam  address$1 = 24'h11;
    
    // Stub signals
    reg  [63:0] r$0$d;
    wire  [63:0] r$0$q;
    reg  r$0$clock;
    reg  [63:0] r$1$d;
    wire  [63:0] r$1$q;
    reg  r$1$clock;
    
    // Sub module instances
    top$pipeline$shade$1$lighting$regs$r$0 r$0(
        .d(r$0$d),
        .q(r$0$q),
        .clock(r$0$clock)
    );
    top$pipeline$shade$1$lighting$regs$r$1 r$1(
        .d(r$1$d),
        .q(r$1$q),
        .clock(r$1$clock)
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
    end
    
endmodule // top$pipeline$shade$1$lighting$regs
module top$pipeline$shade$1$lighting$regs$r$0(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$lighting$regs$r$0
module top$pipeline$shade$1$lighting$regs$r$1(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$lighting$regs$r$1
module top$pipeline$shade$1$lighting$rn(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$lighting$rn
module top$pipeline$shade$1$lighting$rn_3(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$lighting$rn_3
module top$pipeline$shade$1$lighting$rnorm(address,data);
    
    // Module arguments
    input wire  [9:0] address;
    output reg  [15:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        10'b0: data = 16'h0;
      10'b1: data = 16'h8000;
      10'b10: data = 16'h5a82;
      10'b11: data = 16'h49e7;
      10'b100: data = 16'h4000;
      10'b101: data = 16'h393e;
      10'b110: data = 16'h3441;
      10'b111: data = 16'h3061;
      10'b1000: data = 16'h2d41;
      10'b1001: data = 16'h2aab;
      10'b1010: data = 16'h287a;
      10'b1011: data = 16'h2698;
      10'b1100: data = 16'h24f3;
      10'b1101: data = 16'h2380;
      10'b1110: data = 16'h2236;
      10'b1111: data = 16'h210d;
      10'b10000: data = 16'h2000;
      10'b10001: data = 16'h1f0b;
      10'b10010: data = 16'h1e2b;
      10'b10011: data = 16'h1d5d;
      10'b10100: data = 16'h1c9f;
      10'b10101: data = 16'h1bef;
      10'b10110: data = 16'h1b4a;
      10'b10111: data = 16'h1ab1;
      10'b11000: data = 16'h1a21;
      10'b11001: data = 16'h199a;
      10'b11010: data = 16'h191a;
      10'b11011: data = 16'h18a2;
      10'b11100: data = 16'h1831;
      10'b11101: data = 16'h17c5;
      10'b11110: data = 16'h175f;
      10'b11111: data = 16'h16fd;
      10'b100000: data = 16'h16a1;
      10'b100001: data = 16'h1648;
      10'b100010: data = 16'h15f4;
      10'b100011: data = 16'h15a3;
      10'b100100: data = 16'h1555;
      10'b100101: data = 16'h150b;
      10'b100110: data = 16'h14c4;
      10'b100111: data = 16'h147f;
      10'b101000: data = 16'h143d;
      10'b101001: data = 16'h13fe;
      10'b101010: data = 16'h13c0;
      10'b101011: data = 16'h1385;
      10'b101100: data = 16'h134c;
      10'b101101: data = 16'h1315;
      10'b101110: data = 16'h12df;
      10'b101111: data = 16'h12ac;
      10'b110000: data = 16'h127a;
      10'b110001: data = 16'h1249;
      10'b110010: data = 16'h121a;
      10'b110011: data = 16'h11ec;
      10'b110100: data = 16'h11c0;
      10'b110101: data = 16'h1195;
      10'b110110: data = 16'h116b;
      10'b110111: data = 16'h1142;
      10'b111000: data = 16'h111b;
      10'b111001: data = 16'h10f4;
      10'b111010: data = 16'h10cf;
      10'b111011: data = 16'h10aa;
      10'b111100: data = 16'h1086;
      10'b111101: data = 16'h1064;
      10'b111110: data = 16'h1042;
      10'b111111: data = 16'h1020;
      10'b1000000: data = 16'h1000;
      10'b1000001: data = 16'hfe0;
      10'b1000010: data = 16'hfc1;
      10'b1000011: data = 16'hfa3;
      10'b1000100: data = 16'hf86;
      10'b1000101: data = 16'hf69;
      10'b1000110: data = 16'hf4d;
      10'b1000111: data = 16'hf31;
      10'b1001000: data = 16'hf16;
      10'b1001001: data = 16'hefb;
      10'b1001010: data = 16'hee1;
      10'b1001011: data = 16'hec8;
      10'b1001100: data = 16'heaf;
      10'b1001101: data = 16'he96;
      10'b1001110: data = 16'he7e;
      10'b1001111: data = 16'he67;
      10'b1010000: data = 16'he50;
      10'b1010001: data = 16'he39;
      10'b1010010: data = 16'he23;
      10'b1010011: data = 16'he0d;
      10'b1010100: data = 16'hdf7;
      10'b1010101: data = 16'hde2;
      10'b1010110: data = 16'hdcd;
      10'b1010111: data = 16'hdb9;
      10'b1011000: data = 16'hda5;
      10'b1011001: data = 16'hd91;
      10'b1011010: data = 16'hd7e;
      10'b1011011: data = 16'hd6b;
      10'b1011100: data = 16'hd58;
      10'b1011101: data = 16'hd46;
      10'b1011110: data = 16'hd34;
      10'b1011111: data = 16'hd22;
      10'b1100000: data = 16'hd10;
      10'b1100001: data = 16'hcff;
      10'b1100010: data = 16'hcee;
      10'b1100011: data = 16'hcdd;
      10'b1100100: data = 16'hccd;
      10'b1100101: data = 16'hcbd;
      10'b1100110: data = 16'hcad;
      10'b1100111: data = 16'hc9d;
      10'b1101000: data = 16'hc8d;
      10'b1101001: data = 16'hc7e;
      10'b1101010: data = 16'hc6f;
      10'b1101011: data = 16'hc60;
      10'b1101100: data = 16'hc51;
      10'b1101101: data = 16'hc43;
      10'b1101110: data = 16'hc34;
      10'b1101111: data = 16'hc26;
      10'b1110000: data = 16'hc18;
      10'b1110001: data = 16'hc0b;
      10'b1110010: data = 16'hbfd;
      10'b1110011: data = 16'hbf0;
      10'b1110100: data = 16'hbe2;
      10'b1110101: data = 16'hbd5;
      10'b1110110: data = 16'hbc9;
      10'b1110111: data = 16'hbbc;
      10'b1111000: data = 16'hbaf;
      10'b1111001: data = 16'hba3;
      10'b1111010: data = 16'hb97;
      10'b1111011: data = 16'hb8b;
      10'b1111100: data = 16'hb7f;
      10'b1111101: data = 16'hb73;
      10'b1111110: data = 16'hb67;
      10'b1111111: data = 16'hb5c;
      10'b10000000: data = 16'hb50;
      10'b10000001: data = 16'hb45;
      10'b10000010: data = 16'hb3a;
      10'b10000011: data = 16'hb2f;
      10'b10000100: data = 16'hb24;
      10'b10000101: data = 16'hb19;
      10'b10000110: data = 16'hb0f;
      10'b10000111: data = 16'hb04;
      10'b10001000: data = 16'hafa;
      10'b10001001: data = 16'haf0;
      10'b10001010: data = 16'hae5;
      10'b10001011: data = 16'hadb;
      10'b10001100: data = 16'had1;
      10'b10001101: data = 16'hac8;
      10'b10001110: data = 16'habe;
      10'b10001111: data = 16'hab4;
      10'b10010000: data = 16'haab;
      10'b10010001: data = 16'haa1;
      10'b10010010: data = 16'ha98;
      10'b10010011: data = 16'ha8f;
      10'b10010100: data = 16'ha86;
      10'b10010101: data = 16'ha7c;
      10'b10010110: data = 16'ha73;
      10'b10010111: data = 16'ha6b;
      10'b10011000: data = 16'ha62;
      10'b10011001: data = 16'ha59;
      10'b10011010: data = 16'ha51;
      10'b10011011: data = 16'ha48;
      10'b10011100: data = 16'ha40;
      10'b10011101: data = 16'ha37;
      10'b10011110: data = 16'ha2f;
      10'b10011111: data = 16'ha27;
      10'b10100000: data = 16'ha1f;
      10'b10100001: data = 16'ha16;
      10'b10100010: data = 16'ha0e;
      10'b10100011: data = 16'ha07;
      10'b10100100: data = 16'h9ff;
      10'b10100101: data = 16'h9f7;
      10'b10100110: data = 16'h9ef;
      10'b10100111: data = 16'h9e8;
      10'b10101000: data = 16'h9e0;
      10'b10101001: data = 16'h9d9;
      10'b10101010: data = 16'h9d1;
      10'b10101011: data = 16'h9ca;
      10'b10101100: data = 16'h9c3;
      10'b10101101: data = 16'h9bb;
      10'b10101110: data = 16'h9b4;
      10'b10101111: data = 16'h9ad;
      10'b10110000: data = 16'h9a6;
      10'b10110001: data = 16'h99f;
      10'b10110010: data = 16'h998;
      10'b10110011: data = 16'h991;
      10'b10110100: data = 16'h98a;
      10'b10110101: data = 16'h984;
      10'b10110110: data = 16'h97d;
      10'b10110111: data = 16'h976;
      10'b10111000: data = 16'h970;
      10'b10111001: data = 16'h969;
      10'b10111010: data = 16'h963;
      10'b10111011: data = 16'h95c;
      10'b10111100: data = 16'h956;
      10'b10111101: data = 16'h950;
      10'b10111110: data = 16'h949;
      10'b10111111: data = 16'h943;
      10'b11000000: data = 16'h93d;
      10'b11000001: data = 16'h937;
      10'b11000010: data = 16'h931;
      10'b11000011: data = 16'h92b;
      10'b11000100: data = 16'h925;
      10'b11000101: data = 16'h91f;
      10'b11000110: data = 16'h919;
      10'b11000111: data = 16'h913;
      10'b11001000: data = 16'h90d;
      10'b11001001: data = 16'h907;
      10'b11001010: data = 16'h902;
      10'b11001011: data = 16'h8fc;
      10'b11001100: data = 16'h8f6;
      10'b11001101: data = 16'h8f1;
      10'b11001110: data = 16'h8eb;
      10'b11001111: data = 16'h8e6;
      10'b11010000: data = 16'h8e0;
      10'b11010001: data = 16'h8db;
      10'b11010010: data = 16'h8d5;
      10'b11010011: data = 16'h8d0;
      10'b11010100: data = 16'h8cb;
      10'b11010101: data = 16'h8c5;
      10'b11010110: data = 16'h8c0;
      10'b11010111: data = 16'h8bb;
      10'b11011000: data = 16'h8b6;
      10'b11011001: data = 16'h8b0;
      10'b11011010: data = 16'h8ab;
      10'b11011011: data = 16'h8a6;
      10'b11011100: data = 16'h8a1;
      10'b11011101: data = 16'h89c;
      10'b11011110: data = 16'h897;
      10'b11011111: data = 16'h892;
      10'b11100000: data = 16'h88d;
      10'b11100001: data = 16'h889;
      10'b11100010: data = 16'h884;
      10'b11100011: data = 16'h87f;
      10'b11100100: data = 16'h87a;
      10'b11100101: data = 16'h875;
      10'b11100110: data = 16'h871;
      10'b11100111: data = 16'h86c;
      10'b11101000: data = 16'h867;
      10'b11101001: data = 16'h863;
      10'b11101010: data = 16'h85e;
      10'b11101011: data = 16'h85a;
      10'b11101100: data = 16'h855;
      10'b11101101: data = 16'h851;
      10'b11101110: data = 16'h84c;
      10'b11101111: data = 16'h848;
      10'b11110000: data = 16'h843;
      10'b11110001: data = 16'h83f;
      10'b11110010: data = 16'h83a;
      10'b11110011: data = 16'h836;
      10'b11110100: data = 16'h832;
      10'b11110101: data = 16'h82d;
      10'b11110110: data = 16'h829;
      10'b11110111: data = 16'h825;
      10'b11111000: data = 16'h821;
      10'b11111001: data = 16'h81d;
      10'b11111010: data = 16'h818;
      10'b11111011: data = 16'h814;
      10'b11111100: data = 16'h810;
      10'b11111101: data = 16'h80c;
      10'b11111110: data = 16'h808;
      10'b11111111: data = 16'h804;
      10'b100000000: data = 16'h800;
      10'b100000001: data = 16'h7fc;
      10'b100000010: data = 16'h7f8;
      10'b100000011: data = 16'h7f4;
      10'b100000100: data = 16'h7f0;
      10'b100000101: data = 16'h7ec;
      10'b100000110: data = 16'h7e8;
      10'b100000111: data = 16'h7e5;
      10'b100001000: data = 16'h7e1;
      10'b100001001: data = 16'h7dd;
      10'b100001010: data = 16'h7d9;
      10'b100001011: data = 16'h7d5;
      10'b100001100: data = 16'h7d2;
      10'b100001101: data = 16'h7ce;
      10'b100001110: data = 16'h7ca;
      10'b100001111: data = 16'h7c7;
      10'b100010000: data = 16'h7c3;
      10'b100010001: data = 16'h7bf;
      10'b100010010: data = 16'h7bc;
      10'b100010011: data = 16'h7b8;
      10'b100010100: data = 16'h7b4;
      10'b100010101: data = 16'h7b1;
      10'b100010110: data = 16'h7ad;
      10'b100010111: data = 16'h7aa;
      10'b100011000: data = 16'h7a6;
      10'b100011001: data = 16'h7a3;
      10'b100011010: data = 16'h79f;
      10'b100011011: data = 16'h79c;
      10'b100011100: data = 16'h798;
      10'b100011101: data = 16'h795;
      10'b100011110: data = 16'h792;
      10'b100011111: data = 16'h78e;
      10'b100100000: data = 16'h78b;
      10'b100100001: data = 16'h788;
      10'b100100010: data = 16'h784;
      10'b100100011: data = 16'h781;
      10'b100100100: data = 16'h77e;
      10'b100100101: data = 16'h77a;
      10'b100100110: data = 16'h777;
      10'b100100111: data = 16'h774;
      10'b100101000: data = 16'h771;
      10'b100101001: data = 16'h76d;
      10'b100101010: data = 16'h76a;
      10'b100101011: data = 16'h767;
      10'b100101100: data = 16'h764;
      10'b100101101: data = 16'h761;
      10'b100101110: data = 16'h75e;
      10'b100101111: data = 16'h75a;
      10'b100110000: data = 16'h757;
      10'b100110001: data = 16'h754;
      10'b100110010: data = 16'h751;
      10'b100110011: data = 16'h74e;
      10'b100110100: data = 16'h74b;
      10'b100110101: data = 16'h748;
      10'b100110110: data = 16'h745;
      10'b100110111: data = 16'h742;
      10'b100111000: data = 16'h73f;
      10'b100111001: data = 16'h73c;
      10'b100111010: data = 16'h739;
      10'b100111011: data = 16'h736;
      10'b100111100: data = 16'h733;
      10'b100111101: data = 16'h730;
      10'b100111110: data = 16'h72e;
      10'b100111111: data = 16'h72b;
      10'b101000000: data = 16'h728;
      10'b101000001: data = 16'h725;
      10'b101000010: data = 16'h722;
      10'b101000011: data = 16'h71f;
      10'b101000100: data = 16'h71c;
      10'b101000101: data = 16'h71a;
      10'b101000110: data = 16'h717;
      10'b101000111: data = 16'h714;
      10'b101001000: data = 16'h711;
      10'b101001001: data = 16'h70f;
      10'b101001010: data = 16'h70c;
      10'b101001011: data = 16'h709;
      10'b101001100: data = 16'h706;
      10'b101001101: data = 16'h704;
      10'b101001110: data = 16'h701;
      10'b101001111: data = 16'h6fe;
      10'b101010000: data = 16'h6fc;
      10'b101010001: data = 16'h6f9;
      10'b101010010: data = 16'h6f6;
      10'b101010011: data = 16'h6f4;
      10'b101010100: data = 16'h6f1;
      10'b101010101: data = 16'h6ee;
      10'b101010110: data = 16'h6ec;
      10'b101010111: data = 16'h6e9;
      10'b101011000: data = 16'h6e7;
      10'b101011001: data = 16'h6e4;
      10'b101011010: data = 16'h6e2;
      10'b101011011: data = 16'h6df;
      10'b101011100: data = 16'h6dd;
      10'b101011101: data = 16'h6da;
      10'b101011110: data = 16'h6d8;
      10'b101011111: data = 16'h6d5;
      10'b101100000: data = 16'h6d3;
      10'b101100001: data = 16'h6d0;
      10'b101100010: data = 16'h6ce;
      10'b101100011: data = 16'h6cb;
      10'b101100100: data = 16'h6c9;
      10'b101100101: data = 16'h6c6;
      10'b101100110: data = 16'h6c4;
      10'b101100111: data = 16'h6c1;
      10'b101101000: data = 16'h6bf;
      10'b101101001: data = 16'h6bd;
      10'b101101010: data = 16'h6ba;
      10'b101101011: data = 16'h6b8;
      10'b101101100: data = 16'h6b6;
      10'b101101101: data = 16'h6b3;
      10'b101101110: data = 16'h6b1;
      10'b101101111: data = 16'h6ae;
      10'b101110000: data = 16'h6ac;
      10'b101110001: data = 16'h6aa;
      10'b101110010: data = 16'h6a8;
      10'b101110011: data = 16'h6a5;
      10'b101110100: data = 16'h6a3;
      10'b101110101: data = 16'h6a1;
      10'b101110110: data = 16'h69e;
      10'b101110111: data = 16'h69c;
      10'b101111000: data = 16'h69a;
      10'b101111001: data = 16'h698;
      10'b101111010: data = 16'h695;
      10'b101111011: data = 16'h693;
      10'b101111100: data = 16'h691;
      10'b101111101: data = 16'h68f;
      10'b101111110: data = 16'h68d;
      10'b101111111: data = 16'h68a;
      10'b110000000: data = 16'h688;
      10'b110000001: data = 16'h686;
      10'b110000010: data = 16'h684;
      10'b110000011: data = 16'h682;
      10'b110000100: data = 16'h680;
      10'b110000101: data = 16'h67d;
      10'b110000110: data = 16'h67b;
      10'b110000111: data = 16'h679;
      10'b110001000: data = 16'h677;
      10'b110001001: data = 16'h675;
      10'b110001010: data = 16'h673;
      10'b110001011: data = 16'h671;
      10'b110001100: data = 16'h66f;
      10'b110001101: data = 16'h66d;
      10'b110001110: data = 16'h66b;
      10'b110001111: data = 16'h668;
      10'b110010000: data = 16'h666;
      10'b110010001: data = 16'h664;
      10'b110010010: data = 16'h662;
      10'b110010011: data = 16'h660;
      10'b110010100: data = 16'h65e;
      10'b110010101: data = 16'h65c;
      10'b110010110: data = 16'h65a;
      10'b110010111: data = 16'h658;
      10'b110011000: data = 16'h656;
      10'b110011001: data = 16'h654;
      10'b110011010: data = 16'h652;
      10'b110011011: data = 16'h650;
      10'b110011100: data = 16'h64e;
      10'b110011101: data = 16'h64c;
      10'b110011110: data = 16'h64a;
      10'b110011111: data = 16'h649;
      10'b110100000: data = 16'h647;
      10'b110100001: data = 16'h645;
      10'b110100010: data = 16'h643;
      10'b110100011: data = 16'h641;
      10'b110100100: data = 16'h63f;
      10'b110100101: data = 16'h63d;
      10'b110100110: data = 16'h63b;
      10'b110100111: data = 16'h639;
      10'b110101000: data = 16'h637;
      10'b110101001: data = 16'h635;
      10'b110101010: data = 16'h634;
      10'b110101011: data = 16'h632;
      10'b110101100: data = 16'h630;
      10'b110101101: data = 16'h62e;
      10'b110101110: data = 16'h62c;
      10'b110101111: data = 16'h62a;
      10'b110110000: data = 16'h629;
      10'b110110001: data = 16'h627;
      10'b110110010: data = 16'h625;
      10'b110110011: data = 16'h623;
      10'b110110100: data = 16'h621;
      10'b110110101: data = 16'h620;
      10'b110110110: data = 16'h61e;
      10'b110110111: data = 16'h61c;
      10'b110111000: data = 16'h61a;
      10'b110111001: data = 16'h618;
      10'b110111010: data = 16'h617;
      10'b110111011: data = 16'h615;
      10'b110111100: data = 16'h613;
      10'b110111101: data = 16'h611;
      10'b110111110: data = 16'h610;
      10'b110111111: data = 16'h60e;
      10'b111000000: data = 16'h60c;
      10'b111000001: data = 16'h60a;
      10'b111000010: data = 16'h609;
      10'b111000011: data = 16'h607;
      10'b111000100: data = 16'h605;
      10'b111000101: data = 16'h604;
      10'b111000110: data = 16'h602;
      10'b111000111: data = 16'h600;
      10'b111001000: data = 16'h5ff;
      10'b111001001: data = 16'h5fd;
      10'b111001010: data = 16'h5fb;
      10'b111001011: data = 16'h5f9;
      10'b111001100: data = 16'h5f8;
      10'b111001101: data = 16'h5f6;
      10'b111001110: data = 16'h5f5;
      10'b111001111: data = 16'h5f3;
      10'b111010000: data = 16'h5f1;
      10'b111010001: data = 16'h5f0;
      10'b111010010: data = 16'h5ee;
      10'b111010011: data = 16'h5ec;
      10'b111010100: data = 16'h5eb;
      10'b111010101: data = 16'h5e9;
      10'b111010110: data = 16'h5e7;
      10'b111010111: data = 16'h5e6;
      10'b111011000: data = 16'h5e4;
      10'b111011001: data = 16'h5e3;
      10'b111011010: data = 16'h5e1;
      10'b111011011: data = 16'h5df;
      10'b111011100: data = 16'h5de;
      10'b111011101: data = 16'h5dc;
      10'b111011110: data = 16'h5db;
      10'b111011111: data = 16'h5d9;
      10'b111100000: data = 16'h5d8;
      10'b111100001: data = 16'h5d6;
      10'b111100010: data = 16'h5d5;
      10'b111100011: data = 16'h5d3;
      10'b111100100: data = 16'h5d1;
      10'b111100101: data = 16'h5d0;
      10'b111100110: data = 16'h5ce;
      10'b111100111: data = 16'h5cd;
      10'b111101000: data = 16'h5cb;
      10'b111101001: data = 16'h5ca;
      10'b111101010: data = 16'h5c8;
      10'b111101011: data = 16'h5c7;
      10'b111101100: data = 16'h5c5;
      10'b111101101: data = 16'h5c4;
      10'b111101110: data = 16'h5c2;
      10'b111101111: data = 16'h5c1;
      10'b111110000: data = 16'h5bf;
      10'b111110001: data = 16'h5be;
      10'b111110010: data = 16'h5bc;
      10'b111110011: data = 16'h5bb;
      10'b111110100: data = 16'h5b9;
      10'b111110101: data = 16'h5b8;
      10'b111110110: data = 16'h5b7;
      10'b111110111: data = 16'h5b5;
      10'b111111000: data = 16'h5b4;
      10'b111111001: data = 16'h5b2;
      10'b111111010: data = 16'h5b1;
      10'b111111011: data = 16'h5af;
      10'b111111100: data = 16'h5ae;
      10'b111111101: data = 16'h5ac;
      10'b111111110: data = 16'h5ab;
      10'b111111111: data = 16'h5aa;
      10'b1000000000: data = 16'h5a8;
      10'b1000000001: data = 16'h5a7;
      10'b1000000010: data = 16'h5a5;
      10'b1000000011: data = 16'h5a4;
      10'b1000000100: data = 16'h5a3;
      10'b1000000101: data = 16'h5a1;
      10'b1000000110: data = 16'h5a0;
      10'b1000000111: data = 16'h59e;
      10'b1000001000: data = 16'h59d;
      10'b1000001001: data = 16'h59c;
      10'b1000001010: data = 16'h59a;
      10'b1000001011: data = 16'h599;
      10'b1000001100: data = 16'h597;
      10'b1000001101: data = 16'h596;
      10'b1000001110: data = 16'h595;
      10'b1000001111: data = 16'h593;
      10'b1000010000: data = 16'h592;
      10'b1000010001: data = 16'h591;
      10'b1000010010: data = 16'h58f;
      10'b1000010011: data = 16'h58e;
      10'b1000010100: data = 16'h58d;
      10'b1000010101: data = 16'h58b;
      10'b1000010110: data = 16'h58a;
      10'b1000010111: data = 16'h589;
      10'b1000011000: data = 16'h587;
      10'b1000011001: data = 16'h586;
      10'b1000011010: data = 16'h585;
      10'b1000011011: data = 16'h583;
      10'b1000011100: data = 16'h582;
      10'b1000011101: data = 16'h581;
      10'b1000011110: data = 16'h580;
      10'b1000011111: data = 16'h57e;
      10'b1000100000: data = 16'h57d;
      10'b1000100001: data = 16'h57c;
      10'b1000100010: data = 16'h57a;
      10'b1000100011: data = 16'h579;
      10'b1000100100: data = 16'h578;
      10'b1000100101: data = 16'h577;
      10'b1000100110: data = 16'h575;
      10'b1000100111: data = 16'h574;
      10'b1000101000: data = 16'h573;
      10'b1000101001: data = 16'h571;
      10'b1000101010: data = 16'h570;
      10'b1000101011: data = 16'h56f;
      10'b1000101100: data = 16'h56e;
      10'b1000101101: data = 16'h56c;
      10'b1000101110: data = 16'h56b;
      10'b1000101111: data = 16'h56a;
      10'b1000110000: data = 16'h569;
      10'b1000110001: data = 16'h567;
      10'b1000110010: data = 16'h566;
      10'b1000110011: data = 16'h565;
      10'b1000110100: data = 16'h564;
      10'b1000110101: data = 16'h563;
      10'b1000110110: data = 16'h561;
      10'b1000110111: data = 16'h560;
      10'b1000111000: data = 16'h55f;
      10'b1000111001: data = 16'h55e;
      10'b1000111010: data = 16'h55d;
      10'b1000111011: data = 16'h55b;
      10'b1000111100: data = 16'h55a;
      10'b1000111101: data = 16'h559;
      10'b1000111110: data = 16'h558;
      10'b1000111111: data = 16'h557;
      10'b1001000000: data = 16'h555;
      10'b1001000001: data = 16'h554;
      10'b1001000010: data = 16'h553;
      10'b1001000011: data = 16'h552;
      10'b1001000100: data = 16'h551;
      10'b1001000101: data = 16'h54f;
      10'b1001000110: data = 16'h54e;
      10'b1001000111: data = 16'h54d;
      10'b1001001000: data = 16'h54c;
      10'b1001001001: data = 16'h54b;
      10'b1001001010: data = 16'h54a;
      10'b1001001011: data = 16'h548;
      10'b1001001100: data = 16'h547;
      10'b1001001101: data = 16'h546;
      10'b1001001110: data = 16'h545;
      10'b1001001111: data = 16'h544;
      10'b1001010000: data = 16'h543;
      10'b1001010001: data = 16'h542;
      10'b1001010010: data = 16'h540;
      10'b1001010011: data = 16'h53f;
      10'b1001010100: data = 16'h53e;
      10'b1001010101: data = 16'h53d;
      10'b1001010110: data = 16'h53c;
      10'b1001010111: data = 16'h53b;
      10'b1001011000: data = 16'h53a;
      10'b1001011001: data = 16'h539;
      10'b1001011010: data = 16'h538;
      10'b1001011011: data = 16'h536;
      10'b1001011100: data = 16'h535;
      10'b1001011101: data = 16'h534;
      10'b1001011110: data = 16'h533;
      10'b1001011111: data = 16'h532;
      10'b1001100000: data = 16'h531;
      10'b1001100001: data = 16'h530;
      10'b1001100010: data = 16'h52f;
      10'b1001100011: data = 16'h52e;
      10'b1001100100: data = 16'h52d;
      10'b1001100101: data = 16'h52b;
      10'b1001100110: data = 16'h52a;
      10'b1001100111: data = 16'h529;
      10'b1001101000: data = 16'h528;
      10'b1001101001: data = 16'h527;
      10'b1001101010: data = 16'h526;
      10'b1001101011: data = 16'h525;
      10'b1001101100: data = 16'h524;
      10'b1001101101: data = 16'h523;
      10'b1001101110: data = 16'h522;
      10'b1001101111: data = 16'h521;
      10'b1001110000: data = 16'h520;
      10'b1001110001: data = 16'h51f;
      10'b1001110010: data = 16'h51e;
      10'b1001110011: data = 16'h51d;
      10'b1001110100: data = 16'h51c;
      10'b1001110101: data = 16'h51b;
      10'b1001110110: data = 16'h51a;
      10'b1001110111: data = 16'h518;
      10'b1001111000: data = 16'h517;
      10'b1001111001: data = 16'h516;
      10'b1001111010: data = 16'h515;
      10'b1001111011: data = 16'h514;
      10'b1001111100: data = 16'h513;
      10'b1001111101: data = 16'h512;
      10'b1001111110: data = 16'h511;
      10'b1001111111: data = 16'h510;
      10'b1010000000: data = 16'h50f;
      10'b1010000001: data = 16'h50e;
      10'b1010000010: data = 16'h50d;
      10'b1010000011: data = 16'h50c;
      10'b1010000100: data = 16'h50b;
      10'b1010000101: data = 16'h50a;
      10'b1010000110: data = 16'h509;
      10'b1010000111: data = 16'h508;
      10'b1010001000: data = 16'h507;
      10'b1010001001: data = 16'h506;
      10'b1010001010: data = 16'h505;
      10'b1010001011: data = 16'h504;
      10'b1010001100: data = 16'h503;
      10'b1010001101: data = 16'h502;
      10'b1010001110: data = 16'h501;
      10'b1010001111: data = 16'h500;
      10'b1010010000: data = 16'h4ff;
      10'b1010010001: data = 16'h4fe;
      10'b1010010010: data = 16'h4fd;
      10'b1010010011: data = 16'h4fc;
      10'b1010010100: data = 16'h4fb;
      10'b1010010101: data = 16'h4fb;
      10'b1010010110: data = 16'h4fa;
      10'b1010010111: data = 16'h4f9;
      10'b1010011000: data = 16'h4f8;
      10'b1010011001: data = 16'h4f7;
      10'b1010011010: data = 16'h4f6;
      10'b1010011011: data = 16'h4f5;
      10'b1010011100: data = 16'h4f4;
      10'b1010011101: data = 16'h4f3;
      10'b1010011110: data = 16'h4f2;
      10'b1010011111: data = 16'h4f1;
      10'b1010100000: data = 16'h4f0;
      10'b1010100001: data = 16'h4ef;
      10'b1010100010: data = 16'h4ee;
      10'b1010100011: data = 16'h4ed;
      10'b1010100100: data = 16'h4ec;
      10'b1010100101: data = 16'h4eb;
      10'b1010100110: data = 16'h4ea;
      10'b1010100111: data = 16'h4ea;
      10'b1010101000: data = 16'h4e9;
      10'b1010101001: data = 16'h4e8;
      10'b1010101010: data = 16'h4e7;
      10'b1010101011: data = 16'h4e6;
      10'b1010101100: data = 16'h4e5;
      10'b1010101101: data = 16'h4e4;
      10'b1010101110: data = 16'h4e3;
      10'b1010101111: data = 16'h4e2;
      10'b1010110000: data = 16'h4e1;
      10'b1010110001: data = 16'h4e0;
      10'b1010110010: data = 16'h4df;
      10'b1010110011: data = 16'h4df;
      10'b1010110100: data = 16'h4de;
      10'b1010110101: data = 16'h4dd;
      10'b1010110110: data = 16'h4dc;
      10'b1010110111: data = 16'h4db;
      10'b1010111000: data = 16'h4da;
      10'b1010111001: data = 16'h4d9;
      10'b1010111010: data = 16'h4d8;
      10'b1010111011: data = 16'h4d7;
      10'b1010111100: data = 16'h4d7;
      10'b1010111101: data = 16'h4d6;
      10'b1010111110: data = 16'h4d5;
      10'b1010111111: data = 16'h4d4;
      10'b1011000000: data = 16'h4d3;
      10'b1011000001: data = 16'h4d2;
      10'b1011000010: data = 16'h4d1;
      10'b1011000011: data = 16'h4d0;
      10'b1011000100: data = 16'h4cf;
      10'b1011000101: data = 16'h4cf;
      10'b1011000110: data = 16'h4ce;
      10'b1011000111: data = 16'h4cd;
      10'b1011001000: data = 16'h4cc;
      10'b1011001001: data = 16'h4cb;
      10'b1011001010: data = 16'h4ca;
      10'b1011001011: data = 16'h4c9;
      10'b1011001100: data = 16'h4c9;
      10'b1011001101: data = 16'h4c8;
      10'b1011001110: data = 16'h4c7;
      10'b1011001111: data = 16'h4c6;
      10'b1011010000: data = 16'h4c5;
      10'b1011010001: data = 16'h4c4;
      10'b1011010010: data = 16'h4c3;
      10'b1011010011: data = 16'h4c3;
      10'b1011010100: data = 16'h4c2;
      10'b1011010101: data = 16'h4c1;
      10'b1011010110: data = 16'h4c0;
      10'b1011010111: data = 16'h4bf;
      10'b1011011000: data = 16'h4be;
      10'b1011011001: data = 16'h4be;
      10'b1011011010: data = 16'h4bd;
      10'b1011011011: data = 16'h4bc;
      10'b1011011100: data = 16'h4bb;
      10'b1011011101: data = 16'h4ba;
      10'b1011011110: data = 16'h4b9;
      10'b1011011111: data = 16'h4b9;
      10'b1011100000: data = 16'h4b8;
      10'b1011100001: data = 16'h4b7;
      10'b1011100010: data = 16'h4b6;
      10'b1011100011: data = 16'h4b5;
      10'b1011100100: data = 16'h4b5;
      10'b1011100101: data = 16'h4b4;
      10'b1011100110: data = 16'h4b3;
      10'b1011100111: data = 16'h4b2;
      10'b1011101000: data = 16'h4b1;
      10'b1011101001: data = 16'h4b1;
      10'b1011101010: data = 16'h4b0;
      10'b1011101011: data = 16'h4af;
      10'b1011101100: data = 16'h4ae;
      10'b1011101101: data = 16'h4ad;
      10'b1011101110: data = 16'h4ad;
      10'b1011101111: data = 16'h4ac;
      10'b1011110000: data = 16'h4ab;
      10'b1011110001: data = 16'h4aa;
      10'b1011110010: data = 16'h4a9;
      10'b1011110011: data = 16'h4a9;
      10'b1011110100: data = 16'h4a8;
      10'b1011110101: data = 16'h4a7;
      10'b1011110110: data = 16'h4a6;
      10'b1011110111: data = 16'h4a5;
      10'b1011111000: data = 16'h4a5;
      10'b1011111001: data = 16'h4a4;
      10'b1011111010: data = 16'h4a3;
      10'b1011111011: data = 16'h4a2;
      10'b1011111100: data = 16'h4a2;
      10'b1011111101: data = 16'h4a1;
      10'b1011111110: data = 16'h4a0;
      10'b1011111111: data = 16'h49f;
      10'b1100000000: data = 16'h49e;
      10'b1100000001: data = 16'h49e;
      10'b1100000010: data = 16'h49d;
      10'b1100000011: data = 16'h49c;
      10'b1100000100: data = 16'h49b;
      10'b1100000101: data = 16'h49b;
      10'b1100000110: data = 16'h49a;
      10'b1100000111: data = 16'h499;
      10'b1100001000: data = 16'h498;
      10'b1100001001: data = 16'h498;
      10'b1100001010: data = 16'h497;
      10'b1100001011: data = 16'h496;
      10'b1100001100: data = 16'h495;
      10'b1100001101: data = 16'h495;
      10'b1100001110: data = 16'h494;
      10'b1100001111: data = 16'h493;
      10'b1100010000: data = 16'h492;
      10'b1100010001: data = 16'h492;
      10'b1100010010: data = 16'h491;
      10'b1100010011: data = 16'h490;
      10'b1100010100: data = 16'h48f;
      10'b1100010101: data = 16'h48f;
      10'b1100010110: data = 16'h48e;
      10'b1100010111: data = 16'h48d;
      10'b1100011000: data = 16'h48c;
      10'b1100011001: data = 16'h48c;
      10'b1100011010: data = 16'h48b;
      10'b1100011011: data = 16'h48a;
      10'b1100011100: data = 16'h489;
      10'b1100011101: data = 16'h489;
      10'b1100011110: data = 16'h488;
      10'b1100011111: data = 16'h487;
      10'b1100100000: data = 16'h487;
      10'b1100100001: data = 16'h486;
      10'b1100100010: data = 16'h485;
      10'b1100100011: data = 16'h484;
      10'b1100100100: data = 16'h484;
      10'b1100100101: data = 16'h483;
      10'b1100100110: data = 16'h482;
      10'b1100100111: data = 16'h481;
      10'b1100101000: data = 16'h481;
      10'b1100101001: data = 16'h480;
      10'b1100101010: data = 16'h47f;
      10'b1100101011: data = 16'h47f;
      10'b1100101100: data = 16'h47e;
      10'b1100101101: data = 16'h47d;
      10'b1100101110: data = 16'h47d;
      10'b1100101111: data = 16'h47c;
      10'b1100110000: data = 16'h47b;
      10'b1100110001: data = 16'h47a;
      10'b1100110010: data = 16'h47a;
      10'b1100110011: data = 16'h479;
      10'b1100110100: data = 16'h478;
      10'b1100110101: data = 16'h478;
      10'b1100110110: data = 16'h477;
      10'b1100110111: data = 16'h476;
      10'b1100111000: data = 16'h476;
      10'b1100111001: data = 16'h475;
      10'b1100111010: data = 16'h474;
      10'b1100111011: data = 16'h473;
      10'b1100111100: data = 16'h473;
      10'b1100111101: data = 16'h472;
      10'b1100111110: data = 16'h471;
      10'b1100111111: data = 16'h471;
      10'b1101000000: data = 16'h470;
      10'b1101000001: data = 16'h46f;
      10'b1101000010: data = 16'h46f;
      10'b1101000011: data = 16'h46e;
      10'b1101000100: data = 16'h46d;
      10'b1101000101: data = 16'h46d;
      10'b1101000110: data = 16'h46c;
      10'b1101000111: data = 16'h46b;
      10'b1101001000: data = 16'h46b;
      10'b1101001001: data = 16'h46a;
      10'b1101001010: data = 16'h469;
      10'b1101001011: data = 16'h469;
      10'b1101001100: data = 16'h468;
      10'b1101001101: data = 16'h467;
      10'b1101001110: data = 16'h467;
      10'b1101001111: data = 16'h466;
      10'b1101010000: data = 16'h465;
      10'b1101010001: data = 16'h465;
      10'b1101010010: data = 16'h464;
      10'b1101010011: data = 16'h463;
      10'b1101010100: data = 16'h463;
      10'b1101010101: data = 16'h462;
      10'b1101010110: data = 16'h461;
      10'b1101010111: data = 16'h461;
      10'b1101011000: data = 16'h460;
      10'b1101011001: data = 16'h45f;
      10'b1101011010: data = 16'h45f;
      10'b1101011011: data = 16'h45e;
      10'b1101011100: data = 16'h45d;
      10'b1101011101: data = 16'h45d;
      10'b1101011110: data = 16'h45c;
      10'b1101011111: data = 16'h45b;
      10'b1101100000: data = 16'h45b;
      10'b1101100001: data = 16'h45a;
      10'b1101100010: data = 16'h45a;
      10'b1101100011: data = 16'h459;
      10'b1101100100: data = 16'h458;
      10'b1101100101: data = 16'h458;
      10'b1101100110: data = 16'h457;
      10'b1101100111: data = 16'h456;
      10'b1101101000: data = 16'h456;
      10'b1101101001: data = 16'h455;
      10'b1101101010: data = 16'h454;
      10'b1101101011: data = 16'h454;
      10'b1101101100: data = 16'h453;
      10'b1101101101: data = 16'h452;
      10'b1101101110: data = 16'h452;
      10'b1101101111: data = 16'h451;
      10'b1101110000: data = 16'h451;
      10'b1101110001: data = 16'h450;
      10'b1101110010: data = 16'h44f;
      10'b1101110011: data = 16'h44f;
      10'b1101110100: data = 16'h44e;
      10'b1101110101: data = 16'h44d;
      10'b1101110110: data = 16'h44d;
      10'b1101110111: data = 16'h44c;
      10'b1101111000: data = 16'h44c;
      10'b1101111001: data = 16'h44b;
      10'b1101111010: data = 16'h44a;
      10'b1101111011: data = 16'h44a;
      10'b1101111100: data = 16'h449;
      10'b1101111101: data = 16'h449;
      10'b1101111110: data = 16'h448;
      10'b1101111111: data = 16'h447;
      10'b1110000000: data = 16'h447;
      10'b1110000001: data = 16'h446;
      10'b1110000010: data = 16'h445;
      10'b1110000011: data = 16'h445;
      10'b1110000100: data = 16'h444;
      10'b1110000101: data = 16'h444;
      10'b1110000110: data = 16'h443;
      10'b1110000111: data = 16'h442;
      10'b1110001000: data = 16'h442;
      10'b1110001001: data = 16'h441;
      10'b1110001010: data = 16'h441;
      10'b1110001011: data = 16'h440;
      10'b1110001100: data = 16'h43f;
      10'b1110001101: data = 16'h43f;
      10'b1110001110: data = 16'h43e;
      10'b1110001111: data = 16'h43e;
      10'b1110010000: data = 16'h43d;
      10'b1110010001: data = 16'h43c;
      10'b1110010010: data = 16'h43c;
      10'b1110010011: data = 16'h43b;
      10'b1110010100: data = 16'h43b;
      10'b1110010101: data = 16'h43a;
      10'b1110010110: data = 16'h43a;
      10'b1110010111: data = 16'h439;
      10'b1110011000: data = 16'h438;
      10'b1110011001: data = 16'h438;
      10'b1110011010: data = 16'h437;
      10'b1110011011: data = 16'h437;
      10'b1110011100: data = 16'h436;
      10'b1110011101: data = 16'h435;
      10'b1110011110: data = 16'h435;
      10'b1110011111: data = 16'h434;
      10'b1110100000: data = 16'h434;
      10'b1110100001: data = 16'h433;
      10'b1110100010: data = 16'h433;
      10'b1110100011: data = 16'h432;
      10'b1110100100: data = 16'h431;
      10'b1110100101: data = 16'h431;
      10'b1110100110: data = 16'h430;
      10'b1110100111: data = 16'h430;
      10'b1110101000: data = 16'h42f;
      10'b1110101001: data = 16'h42e;
      10'b1110101010: data = 16'h42e;
      10'b1110101011: data = 16'h42d;
      10'b1110101100: data = 16'h42d;
      10'b1110101101: data = 16'h42c;
      10'b1110101110: data = 16'h42c;
      10'b1110101111: data = 16'h42b;
      10'b1110110000: data = 16'h42b;
      10'b1110110001: data = 16'h42a;
      10'b1110110010: data = 16'h429;
      10'b1110110011: data = 16'h429;
      10'b1110110100: data = 16'h428;
      10'b1110110101: data = 16'h428;
      10'b1110110110: data = 16'h427;
      10'b1110110111: data = 16'h427;
      10'b1110111000: data = 16'h426;
      10'b1110111001: data = 16'h425;
      10'b1110111010: data = 16'h425;
      10'b1110111011: data = 16'h424;
      10'b1110111100: data = 16'h424;
      10'b1110111101: data = 16'h423;
      10'b1110111110: data = 16'h423;
      10'b1110111111: data = 16'h422;
      10'b1111000000: data = 16'h422;
      10'b1111000001: data = 16'h421;
      10'b1111000010: data = 16'h420;
      10'b1111000011: data = 16'h420;
      10'b1111000100: data = 16'h41f;
      10'b1111000101: data = 16'h41f;
      10'b1111000110: data = 16'h41e;
      10'b1111000111: data = 16'h41e;
      10'b1111001000: data = 16'h41d;
      10'b1111001001: data = 16'h41d;
      10'b1111001010: data = 16'h41c;
      10'b1111001011: data = 16'h41c;
      10'b1111001100: data = 16'h41b;
      10'b1111001101: data = 16'h41a;
      10'b1111001110: data = 16'h41a;
      10'b1111001111: data = 16'h419;
      10'b1111010000: data = 16'h419;
      10'b1111010001: data = 16'h418;
      10'b1111010010: data = 16'h418;
      10'b1111010011: data = 16'h417;
      10'b1111010100: data = 16'h417;
      10'b1111010101: data = 16'h416;
      10'b1111010110: data = 16'h416;
      10'b1111010111: data = 16'h415;
      10'b1111011000: data = 16'h415;
      10'b1111011001: data = 16'h414;
      10'b1111011010: data = 16'h414;
      10'b1111011011: data = 16'h413;
      10'b1111011100: data = 16'h412;
      10'b1111011101: data = 16'h412;
      10'b1111011110: data = 16'h411;
      10'b1111011111: data = 16'h411;
      10'b1111100000: data = 16'h410;
      10'b1111100001: data = 16'h410;
      10'b1111100010: data = 16'h40f;
      10'b1111100011: data = 16'h40f;
      10'b1111100100: data = 16'h40e;
      10'b1111100101: data = 16'h40e;
      10'b1111100110: data = 16'h40d;
      10'b1111100111: data = 16'h40d;
      10'b1111101000: data = 16'h40c;
      10'b1111101001: data = 16'h40c;
      10'b1111101010: data = 16'h40b;
      10'b1111101011: data = 16'h40b;
      10'b1111101100: data = 16'h40a;
      10'b1111101101: data = 16'h40a;
      10'b1111101110: data = 16'h409;
      10'b1111101111: data = 16'h409;
      10'b1111110000: data = 16'h408;
      10'b1111110001: data = 16'h408;
      10'b1111110010: data = 16'h407;
      10'b1111110011: data = 16'h407;
      10'b1111110100: data = 16'h406;
      10'b1111110101: data = 16'h406;
      10'b1111110110: data = 16'h405;
      10'b1111110111: data = 16'h405;
      10'b1111111000: data = 16'h404;
      10'b1111111001: data = 16'h404;
      10'b1111111010: data = 16'h403;
      10'b1111111011: data = 16'h403;
      10'b1111111100: data = 16'h402;
      10'b1111111101: data = 16'h402;
      10'b1111111110: data = 16'h401;
      10'b1111111111: data = 16'h401;
      default: data = 16'h0;
    endcase
            
endmodule // top$pipeline$shade$1$lighting$rnorm
module top$pipeline$shade$1$lighting$sh_q$0(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$lighting$sh_q$0
module top$pipeline$shade$1$lighting$sh_q$1(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$lighting$sh_q$1
module top$pipeline$shade$1$lighting$sh_q$2(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$lighting$sh_q$2
module top$pipeline$shade$1$lighting$sl_q$0(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$lighting$sl_q$0
module top$pipeline$shade$1$lighting$sl_q$1(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$lighting$sl_q$1
module top$pipeline$shade$1$lighting$sl_q$2(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$lighting$sl_q$2
module top$pipeline$shade$1$lighting$specular_q(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$lighting$specular_q
module top$pipeline$shade$1$lighting$specular_table(clock,host_write,host_address,host_data,address,data);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  [9:0] address;
    output reg  [15:0] data;
    
    // Constant declarations
    localparam  base = 24'h31000;
    localparam  window = 24'h31400;
    
    // Stub signals
    reg  [9:0] ram$read_address;
    reg  ram$read_clock;
    wire  [15:0] ram$read_data;
    reg  [9:0] ram$write_address;
    reg  ram$write_clock;
    reg  [15:0] ram$write_data;
    reg  ram$write_enable;
    
    // Sub module instances
    top$pipeline$shade$1$lighting$specular_table$ram ram(
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
        ram$write_address = 10'(host_address - base);
        ram$write_data = 16'(host_data);
        ram$read_address = address;
        data = ram$read_data;
    end
    
endmodule // top$pipeline$shade$1$lighting$specular_table
module top$pipeline$shade$1$lighting$specular_table$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [9:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [9:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [7:0] mem[1023:0];
    
    always @(posedge read_clock) begin
       read_data <= {8'd0, mem[read_address[9:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[9:0]] <= {write_data[7:0]};
       end
    end
endmodule // top$pipeline$shade$1$lighting$specular_table$ram
module top$pipeline$shade$1$lighting$square$0(address,data);
    
    // Module arguments
    input wire  [3:0] address;
    output reg  [7:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        4'h0: data = 8'h0;
      4'h1: data = 8'h1;
      4'h2: data = 8'h4;
      4'h3: data = 8'h9;
      4'h4: data = 8'h10;
      4'h5: data = 8'h19;
      4'h6: data = 8'h24;
      4'h7: data = 8'h31;
      4'h8: data = 8'h40;
      4'h9: data = 8'h51;
      4'ha: data = 8'h64;
      4'hb: data = 8'h79;
      4'hc: data = 8'h90;
      4'hd: data = 8'ha9;
      4'he: data = 8'hc4;
      4'hf: data = 8'he1;
      default: data = 8'h0;
    endcase
            
endmodule // top$pipeline$shade$1$lighting$square$0
module top$pipeline$shade$1$lighting$square$1(address,data);
    
    // Module arguments
    input wire  [3:0] address;
    output reg  [7:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        4'h0: data = 8'h0;
      4'h1: data = 8'h1;
      4'h2: data = 8'h4;
      4'h3: data = 8'h9;
      4'h4: data = 8'h10;
      4'h5: data = 8'h19;
      4'h6: data = 8'h24;
      4'h7: data = 8'h31;
      4'h8: data = 8'h40;
      4'h9: data = 8'h51;
      4'ha: data = 8'h64;
      4'hb: data = 8'h79;
      4'hc: data = 8'h90;
      4'hd: data = 8'ha9;
      4'he: data = 8'hc4;
      4'hf: data = 8'he1;
      default: data = 8'h0;
    endcase
            
endmodule // top$pipeline$shade$1$lighting$square$1
module top$pipeline$shade$1$lighting$square$2(address,data);
    
    // Module arguments
    input wire  [3:0] address;
    output reg  [7:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        4'h0: data = 8'h0;
      4'h1: data = 8'h1;
      4'h2: data = 8'h4;
      4'h3: data = 8'h9;
      4'h4: data = 8'h10;
      4'h5: data = 8'h19;
      4'h6: data = 8'h24;
      4'h7: data = 8'h31;
      4'h8: data = 8'h40;
      4'h9: data = 8'h51;
      4'ha: data = 8'h64;
      4'hb: data = 8'h79;
      4'hc: data = 8'h90;
      4'hd: data = 8'ha9;
      4'he: data = 8'hc4;
      4'hf: data = 8'he1;
      default: data = 8'h0;
    endcase
            
endmodule // top$pipeline$shade$1$lighting$square$2
module top$pipeline$shade$1$lighting$t_h(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$lighting$t_h
module top$pipeline$shade$1$lighting$t_l(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$lighting$t_l
module top$pipeline$shade$1$lit_b(clock,a,b,y);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  half = 'h80;
    localparam  shift = 8'h8;
    localparam  enabled = 1'b1;
    
    // Stub signals
    reg  [31:0] t$d;
    wire  [31:0] t$q;
    reg  t$clock;
    
    // Sub module instances
    top$pipeline$shade$1$lit_b$t t(
        .d(t$d),
        .q(t$q),
        .clock(t$clock)
    );
    
    // Update code
    reg  [15:0] y_pass;
    always @(*) begin
        t$clock = clock;
        t$d = t$q;
        t$d = a * b + half;
        y_pass = 16'((t$q + (t$q >> shift)) >> shift);
        if (~enabled) begin
            y_pass = 'h0;
        end
        y = y_pass;
    end
    
endmodule // top$pipeline$shade$1$lit_b
module top$pipeline$shade$1$lit_b$t(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$lit_b$t
module top$pipeline$shade$1$lit_g(clock,a,b,y);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  half = 'h80;
    localparam  shift = 8'h8;
    localparam  enabled = 1'b1;
    
    // Stub signals
    reg  [31:0] t$d;
    wire  [31:0] t$q;
    reg  t$clock;
    
    // Sub module instances
    top$pipeline$shade$1$lit_g$t t(
        .d(t$d),
        .q(t$q),
        .clock(t$clock)
    );
    
    // Update code
    reg  [15:0] y_pass;
    always @(*) begin
        t$clock = clock;
        t$d = t$q;
        t$d = a * b + half;
        y_pass = 16'((t$q + (t$q >> shift)) >> shift);
        if (~enabled) begin
            y_pass = 'h0;
        end
        y = y_pass;
    end
    
endmodule // top$pipeline$shade$1$lit_g
module top$pipeline$shade$1$lit_g$t(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$lit_g$t
module top$pipeline$shade$1$lit_r(clock,a,b,y);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  half = 'h80;
    localparam  shift = 8'h8;
    localparam  enabled = 1'b1;
    
    // Stub signals
    reg  [31:0] t$d;
    wire  [31:0] t$q;
    reg  t$clock;
    
    // Sub module instances
    top$pipeline$shade$1$lit_r$t t(
        .d(t$d),
        .q(t$q),
        .clock(t$clock)
    );
    
    // Update code
    reg  [15:0] y_pass;
    always @(*) begin
        t$clock = clock;
        t$d = t$q;
        t$d = a * b + half;
        y_pass = 16'((t$q + (t$q >> shift)) >> shift);
        if (~enabled) begin
            y_pass = 'h0;
        end
        y = y_pass;
    end
    
endmodule // top$pipeline$shade$1$lit_r
module top$pipeline$shade$1$lit_r$t(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$lit_r$t
module top$pipeline$shade$1$lut(clock,host_write,host_address,host_data,address,data);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  [11:0] address;
    output reg  [63:0] data;
    
    // Constant declarations
    localparam  base = 24'h10000;
    localparam  window = 24'h11000;
    
    // Stub signals
    reg  [11:0] ram$read_address;
    reg  ram$read_clock;
    wire  [63:0] ram$read_data;
    reg  [11:0] ram$write_address;
    reg  ram$write_clock;
    reg  [63:0] ram$write_data;
    reg  ram$write_enable;
    
    // Sub module instances
    top$pipeline$shade$1$lut$ram ram(
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
        ram$write_data = 64'(host_data);
        ram$read_address = address;
        data = ram$read_data;
    end
    
endmodule // top$pipeline$shade$1$lut
module top$pipeline$shade$1$lut$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [11:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [11:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [31:0] mem[255:0];
    
    always @(posedge read_clock) begin
       read_data <= {8'd0, mem[read_address[7:0]][31:24], 8'd0, mem[read_address[7:0]][23:16], 8'd0, mem[read_address[7:0]][15:8], 8'd0, mem[read_address[7:0]][7:0]};
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[7:0]] <= {write_data[55:48], write_data[39:32], write_data[23:16], write_data[7:0]};
       end
    end
endmodule // top$pipeline$shade$1$lut$ram
module top$pipeline$shade$1$lut_q$0(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$lut_q$0
module top$pipeline$shade$1$lut_q$1(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$lut_q$1
module top$pipeline$shade$1$lut_q$2(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$lut_q$2
module top$pipeline$shade$1$lut_q$3(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$lut_q$3
module top$pipeline$shade$1$lut_q$4(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$lut_q$4
module top$pipeline$shade$1$lut_q$5(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$lut_q$5
module top$pipeline$shade$1$lut_q$6(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$lut_q$6
module top$pipeline$shade$1$lut_q$7(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$lut_q$7
module top$pipeline$shade$1$lut_q$8(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$lut_q$8
module top$pipeline$shade$1$mag_in$0(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$mag_in$0
module top$pipeline$shade$1$mag_in$1(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$mag_in$1
module top$pipeline$shade$1$mag_in$2(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$mag_in$2
module top$pipeline$shade$1$mul_b(clock,a,b,y);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  half = 'h80;
    localparam  shift = 8'h8;
    localparam  enabled = 1'b1;
    
    // Stub signals
    reg  [31:0] t$d;
    wire  [31:0] t$q;
    reg  t$clock;
    
    // Sub module instances
    top$pipeline$shade$1$mul_b$t t(
        .d(t$d),
        .q(t$q),
        .clock(t$clock)
    );
    
    // Update code
    reg  [15:0] y_pass;
    always @(*) begin
        t$clock = clock;
        t$d = t$q;
        t$d = a * b + half;
        y_pass = 16'((t$q + (t$q >> shift)) >> shift);
        if (~enabled) begin
            y_pass = 'h0;
        end
        y = y_pass;
    end
    
endmodule // top$pipeline$shade$1$mul_b
module top$pipeline$shade$1$mul_b$t(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$mul_b$t
module top$pipeline$shade$1$mul_g(clock,a,b,y);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  half = 'h80;
    localparam  shift = 8'h8;
    localparam  enabled = 1'b1;
    
    // Stub signals
    reg  [31:0] t$d;
    wire  [31:0] t$q;
    reg  t$clock;
    
    // Sub module instances
    top$pipeline$shade$1$mul_g$t t(
        .d(t$d),
        .q(t$q),
        .clock(t$clock)
    );
    
    // Update code
    reg  [15:0] y_pass;
    always @(*) begin
        t$clock = clock;
        t$d = t$q;
        t$d = a * b + half;
        y_pass = 16'((t$q + (t$q >> shift)) >> shift);
        if (~enabled) begin
            y_pass = 'h0;
        end
        y = y_pass;
    end
    
endmodule // top$pipeline$shade$1$mul_g
module top$pipeline$shade$1$mul_g$t(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$mul_g$t
module top$pipeline$shade$1$mul_r(clock,a,b,y);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  half = 'h80;
    localparam  shift = 8'h8;
    localparam  enabled = 1'b1;
    
    // Stub signals
    reg  [31:0] t$d;
    wire  [31:0] t$q;
    reg  t$clock;
    
    // Sub module instances
    top$pipeline$shade$1$mul_r$t t(
        .d(t$d),
        .q(t$q),
        .clock(t$clock)
    );
    
    // Update code
    reg  [15:0] y_pass;
    always @(*) begin
        t$clock = clock;
        t$d = t$q;
        t$d = a * b + half;
        y_pass = 16'((t$q + (t$q >> shift)) >> shift);
        if (~enabled) begin
            y_pass = 'h0;
        end
        y = y_pass;
    end
    
endmodule // top$pipeline$shade$1$mul_r
module top$pipeline$shade$1$mul_r$t(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$mul_r$t
module top$pipeline$shade$1$neg_in$0(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$neg_in$0
module top$pipeline$shade$1$neg_in$1(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$neg_in$1
module top$pipeline$shade$1$neg_in$2(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$neg_in$2
module top$pipeline$shade$1$normal(clock,neg$0,neg$1,neg$2,mag$0,mag$1,mag$2,q_neg$0,q_neg$1,q_neg$2,q_mag$0,q_mag$1,q_mag$2);
    
    // Module arguments
    input wire  clock;
    input wire  neg$0;
    input wire  neg$1;
    input wire  neg$2;
    input wire  [31:0] mag$0;
    input wire  [31:0] mag$1;
    input wire  [31:0] mag$2;
    output reg  q_neg$0;
    output reg  q_neg$1;
    output reg  q_neg$2;
    output reg  [3:0] q_mag$0;
    output reg  [3:0] q_mag$1;
    output reg  [3:0] q_mag$2;
    
    // Constant declarations
    localparam  bit_len$0 = 8'h1;
    localparam  bit_len$1 = 8'h2;
    localparam  bit_len$2 = 8'h3;
    localparam  bit_len$3 = 8'h4;
    localparam  bit_len$4 = 8'h5;
    localparam  bit_len$5 = 8'h6;
    localparam  bit_len$6 = 8'h7;
    localparam  bit_len$7 = 8'h8;
    localparam  bit_len$8 = 8'h9;
    localparam  bit_len$9 = 8'ha;
    localparam  bit_len$10 = 8'hb;
    localparam  bit_len$11 = 8'hc;
    localparam  bit_len$12 = 8'hd;
    localparam  bit_len$13 = 8'he;
    localparam  bit_len$14 = 8'hf;
    localparam  bit_len$15 = 8'h10;
    localparam  bit_len$16 = 8'h11;
    localparam  bit_len$17 = 8'h12;
    localparam  bit_len$18 = 8'h13;
    localparam  bit_len$19 = 8'h14;
    localparam  bit_len$20 = 8'h15;
    localparam  bit_len$21 = 8'h16;
    localparam  bit_len$22 = 8'h17;
    localparam  bit_len$23 = 8'h18;
    localparam  bit_len$24 = 8'h19;
    localparam  bit_len$25 = 8'h1a;
    localparam  bit_len$26 = 8'h1b;
    localparam  bit_len$27 = 8'h1c;
    localparam  bit_len$28 = 8'h1d;
    localparam  bit_len$29 = 8'h1e;
    localparam  bit_len$30 = 8'h1f;
    localparam  bit_len$31 = 8'h20;
    
    // Stub signals
    reg  [7:0] s_q$d;
    wire  [7:0] s_q$q;
    reg  s_q$clock;
    reg  neg_q$0$d;
    wire  neg_q$0$q;
    reg  neg_q$0$clock;
    reg  neg_q$1$d;
    wire  neg_q$1$q;
    reg  neg_q$1$clock;
    reg  neg_q$2$d;
    wire  neg_q$2$q;
    reg  neg_q$2$clock;
    reg  [31:0] mag_q$0$d;
    wire  [31:0] mag_q$0$q;
    reg  mag_q$0$clock;
    reg  [31:0] mag_q$1$d;
    wire  [31:0] mag_q$1$q;
    reg  mag_q$1$clock;
    reg  [31:0] mag_q$2$d;
    wire  [31:0] mag_q$2$q;
    reg  mag_q$2$clock;
    reg  [7:0] s_q2$d;
    wire  [7:0] s_q2$q;
    reg  s_q2$clock;
    reg  neg_q2$0$d;
    wire  neg_q2$0$q;
    reg  neg_q2$0$clock;
    reg  neg_q2$1$d;
    wire  neg_q2$1$q;
    reg  neg_q2$1$clock;
    reg  neg_q2$2$d;
    wire  neg_q2$2$q;
    reg  neg_q2$2$clock;
    reg  [31:0] sum_q$0$d;
    wire  [31:0] sum_q$0$q;
    reg  sum_q$0$clock;
    reg  [31:0] sum_q$1$d;
    wire  [31:0] sum_q$1$q;
    reg  sum_q$1$clock;
    reg  [31:0] sum_q$2$d;
    wire  [31:0] sum_q$2$q;
    reg  sum_q$2$clock;
    reg  out_neg$0$d;
    wire  out_neg$0$q;
    reg  out_neg$0$clock;
    reg  out_neg$1$d;
    wire  out_neg$1$q;
    reg  out_neg$1$clock;
    reg  out_neg$2$d;
    wire  out_neg$2$q;
    reg  out_neg$2$clock;
    reg  [3:0] out_mag$0$d;
    wire  [3:0] out_mag$0$q;
    reg  out_mag$0$clock;
    reg  [3:0] out_mag$1$d;
    wire  [3:0] out_mag$1$q;
    reg  out_mag$1$clock;
    reg  [3:0] out_mag$2$d;
    wire  [3:0] out_mag$2$q;
    reg  out_mag$2$clock;
    
    // Local signals
    reg  [31:0] m;
    reg  [7:0] bl;
    reg  [31:0] half;
    reg  [31:0] q$0;
    reg  [31:0] q$1;
    reg  [31:0] q$2;
    
    // Sub module instances
    top$pipeline$shade$1$normal$s_q s_q(
        .d(s_q$d),
        .q(s_q$q),
        .clock(s_q$clock)
    );
    top$pipeline$shade$1$normal$neg_q$0 neg_q$0(
        .d(neg_q$0$d),
        .q(neg_q$0$q),
        .clock(neg_q$0$clock)
    );
    top$pipeline$shade$1$normal$neg_q$1 neg_q$1(
        .d(neg_q$1$d),
        .q(neg_q$1$q),
        .clock(neg_q$1$clock)
    );
    top$pipeline$shade$1$normal$neg_q$2 neg_q$2(
        .d(neg_q$2$d),
        .q(neg_q$2$q),
        .clock(neg_q$2$clock)
    );
    top$pipeline$shade$1$normal$mag_q$0 mag_q$0(
        .d(mag_q$0$d),
        .q(mag_q$0$q),
        .clock(mag_q$0$clock)
    );
    top$pipeline$shade$1$normal$mag_q$1 mag_q$1(
        .d(mag_q$1$d),
        .q(mag_q$1$q),
        .clock(mag_q$1$clock)
    );
    top$pipeline$shade$1$normal$mag_q$2 mag_q$2(
        .d(mag_q$2$d),
        .q(mag_q$2$q),
        .clock(mag_q$2$clock)
    );
    top$pipeline$shade$1$normal$s_q2 s_q2(
        .d(s_q2$d),
        .q(s_q2$q),
        .clock(s_q2$clock)
    );
    top$pipeline$shade$1$normal$neg_q2$0 neg_q2$0(
        .d(neg_q2$0$d),
        .q(neg_q2$0$q),
        .clock(neg_q2$0$clock)
    );
    top$pipeline$shade$1$normal$neg_q2$1 neg_q2$1(
        .d(neg_q2$1$d),
        .q(neg_q2$1$q),
        .clock(neg_q2$1$clock)
    );
    top$pipeline$shade$1$normal$neg_q2$2 neg_q2$2(
        .d(neg_q2$2$d),
        .q(neg_q2$2$q),
        .clock(neg_q2$2$clock)
    );
    top$pipeline$shade$1$normal$sum_q$0 sum_q$0(
        .d(sum_q$0$d),
        .q(sum_q$0$q),
        .clock(sum_q$0$clock)
    );
    top$pipeline$shade$1$normal$sum_q$1 sum_q$1(
        .d(sum_q$1$d),
        .q(sum_q$1$q),
        .clock(sum_q$1$clock)
    );
    top$pipeline$shade$1$normal$sum_q$2 sum_q$2(
        .d(sum_q$2$d),
        .q(sum_q$2$q),
        .clock(sum_q$2$clock)
    );
    top$pipeline$shade$1$normal$out_neg$0 out_neg$0(
        .d(out_neg$0$d),
        .q(out_neg$0$q),
        .clock(out_neg$0$clock)
    );
    top$pipeline$shade$1$normal$out_neg$1 out_neg$1(
        .d(out_neg$1$d),
        .q(out_neg$1$q),
        .clock(out_neg$1$clock)
    );
    top$pipeline$shade$1$normal$out_neg$2 out_neg$2(
        .d(out_neg$2$d),
        .q(out_neg$2$q),
        .clock(out_neg$2$clock)
    );
    top$pipeline$shade$1$normal$out_mag$0 out_mag$0(
        .d(out_mag$0$d),
        .q(out_mag$0$q),
        .clock(out_mag$0$clock)
    );
    top$pipeline$shade$1$normal$out_mag$1 out_mag$1(
        .d(out_mag$1$d),
        .q(out_mag$1$q),
        .clock(out_mag$1$clock)
    );
    top$pipeline$shade$1$normal$out_mag$2 out_mag$2(
        .d(out_mag$2$d),
        .q(out_mag$2$q),
        .clock(out_mag$2$clock)
    );
    
    // Update code
    always @(*) begin
        s_q$clock = clock;
        s_q2$clock = clock;
        s_q$d = s_q$q;
        s_q2$d = s_q2$q;
        m = mag$0 | mag$1 | mag$2;
        bl = 'h0;
        if (m[0]) begin
            bl = bit_len$0;
        end
        if (m[1]) begin
            bl = bit_len$1;
        end
        if (m[2]) begin
            bl = bit_len$2;
        end
        if (m[3]) begin
            bl = bit_len$3;
        end
        if (m[4]) begin
            bl = bit_len$4;
        end
        if (m[5]) begin
            bl = bit_len$5;
        end
        if (m[6]) begin
            bl = bit_len$6;
        end
        if (m[7]) begin
            bl = bit_len$7;
        end
        if (m[8]) begin
            bl = bit_len$8;
        end
        if (m[9]) begin
            bl = bit_len$9;
        end
        if (m[10]) begin
            bl = bit_len$10;
        end
        if (m[11]) begin
            bl = bit_len$11;
        end
        if (m[12]) begin
            bl = bit_len$12;
        end
        if (m[13]) begin
            bl = bit_len$13;
        end
        if (m[14]) begin
            bl = bit_len$14;
        end
        if (m[15]) begin
            bl = bit_len$15;
        end
        if (m[16]) begin
            bl = bit_len$16;
        end
        if (m[17]) begin
            bl = bit_len$17;
        end
        if (m[18]) begin
            bl = bit_len$18;
        end
        if (m[19]) begin
            bl = bit_len$19;
        end
        if (m[20]) begin
            bl = bit_len$20;
        end
        if (m[21]) begin
            bl = bit_len$21;
        end
        if (m[22]) begin
            bl = bit_len$22;
        end
        if (m[23]) begin
            bl = bit_len$23;
        end
        if (m[24]) begin
            bl = bit_len$24;
        end
        if (m[25]) begin
            bl = bit_len$25;
        end
        if (m[26]) begin
            bl = bit_len$26;
        end
        if (m[27]) begin
            bl = bit_len$27;
        end
        if (m[28]) begin
            bl = bit_len$28;
        end
        if (m[29]) begin
            bl = bit_len$29;
        end
        if (m[30]) begin
            bl = bit_len$30;
        end
        if (m[31]) begin
            bl = bit_len$31;
        end
        s_q$d = 'h0;
        if (bl > 'h4) begin
            s_q$d = bl - 'h4;
        end
        half = 'h0;
        if (s_q$q > 'h0) begin
            half = (32'('h1) << s_q$q) >> 'h1;
        end
        s_q2$d = s_q$q;
        neg_q$0$clock = clock;
        mag_q$0$clock = clock;
        neg_q2$0$clock = clock;
        sum_q$0$clock = clock;
        out_neg$0$clock = clock;
        out_mag$0$clock = clock;
        neg_q$0$d = neg$0;
        mag_q$0$d = mag$0;
        neg_q2$0$d = neg_q$0$q;
        sum_q$0$d = mag_q$0$q + half;
        if (neg_q$0$q & (s_q$q > 'h0)) begin
            sum_q$0$d = mag_q$0$q + half - 'h1;
        end
        q$0 = sum_q$0$q >> s_q2$q;
        if (q$0 > 'hf) begin
            q$0 = 'hf;
        end
        out_mag$0$d = q$0[('h0)+:(4)];
        out_neg$0$d = neg_q2$0$q & (q$0 != 'h0);
        q_neg$0 = out_neg$0$q;
        q_mag$0 = out_mag$0$q;
        neg_q$1$clock = clock;
        mag_q$1$clock = clock;
        neg_q2$1$clock = clock;
        sum_q$1$clock = clock;
        out_neg$1$clock = clock;
        out_mag$1$clock = clock;
        neg_q$1$d = neg$1;
        mag_q$1$d = mag$1;
        neg_q2$1$d = neg_q$1$q;
        sum_q$1$d = mag_q$1$q + half;
        if (neg_q$1$q & (s_q$q > 'h0)) begin
            sum_q$1$d = mag_q$1$q + half - 'h1;
        end
        q$1 = sum_q$1$q >> s_q2$q;
        if (q$1 > 'hf) begin
            q$1 = 'hf;
        end
        out_mag$1$d = q$1[('h0)+:(4)];
        out_neg$1$d = neg_q2$1$q & (q$1 != 'h0);
        q_neg$1 = out_neg$1$q;
        q_mag$1 = out_mag$1$q;
        neg_q$2$clock = clock;
        mag_q$2$clock = clock;
        neg_q2$2$clock = clock;
        sum_q$2$clock = clock;
        out_neg$2$clock = clock;
        out_mag$2$clock = clock;
        neg_q$2$d = neg$2;
        mag_q$2$d = mag$2;
        neg_q2$2$d = neg_q$2$q;
        sum_q$2$d = mag_q$2$q + half;
        if (neg_q$2$q & (s_q$q > 'h0)) begin
            sum_q$2$d = mag_q$2$q + half - 'h1;
        end
        q$2 = sum_q$2$q >> s_q2$q;
        if (q$2 > 'hf) begin
            q$2 = 'hf;
        end
        out_mag$2$d = q$2[('h0)+:(4)];
        out_neg$2$d = neg_q2$2$q & (q$2 != 'h0);
        q_neg$2 = out_neg$2$q;
        q_mag$2 = out_mag$2$q;
    end
    
endmodule // top$pipeline$shade$1$normal
module top$pipeline$shade$1$normal$mag_q$0(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$normal$mag_q$0
module top$pipeline$shade$1$normal$mag_q$1(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$normal$mag_q$1
module top$pipeline$shade$1$normal$mag_q$2(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$normal$mag_q$2
module top$pipeline$shade$1$normal$neg_q$0(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$normal$neg_q$0
module top$pipeline$shade$1$normal$neg_q$1(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$normal$neg_q$1
module top$pipeline$shade$1$normal$neg_q$2(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$normal$neg_q$2
module top$pipeline$shade$1$normal$neg_q2$0(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$normal$neg_q2$0
module top$pipeline$shade$1$normal$neg_q2$1(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$normal$neg_q2$1
module top$pipeline$shade$1$normal$neg_q2$2(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$normal$neg_q2$2
module top$pipeline$shade$1$normal$out_mag$0(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$normal$out_mag$0
module top$pipeline$shade$1$normal$out_mag$1(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$normal$out_mag$1
module top$pipeline$shade$1$normal$out_mag$2(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$normal$out_mag$2
module top$pipeline$shade$1$normal$out_neg$0(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$normal$out_neg$0
module top$pipeline$shade$1$normal$out_neg$1(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$normal$out_neg$1
module top$pipeline$shade$1$normal$out_neg$2(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$normal$out_neg$2
module top$pipeline$shade$1$normal$s_q(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$normal$s_q
module top$pipeline$shade$1$normal$s_q2(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$normal$s_q2
module top$pipeline$shade$1$normal$sum_q$0(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$normal$sum_q$0
module top$pipeline$shade$1$normal$sum_q$1(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$normal$sum_q$1
module top$pipeline$shade$1$normal$sum_q$2(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$normal$sum_q$2
module top$pipeline$shade$1$r_q(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$r_q
module top$pipeline$shade$1$row_q$0(d,q,clock);
    
    // Module arguments
    input wire  [11:0] d;
    output reg  [11:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 12'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$row_q$0
module top$pipeline$shade$1$row_q$1(d,q,clock);
    
    // Module arguments
    input wire  [11:0] d;
    output reg  [11:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 12'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$row_q$1
module top$pipeline$shade$1$row_q$2(d,q,clock);
    
    // Module arguments
    input wire  [11:0] d;
    output reg  [11:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 12'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$row_q$2
module top$pipeline$shade$1$row_q$3(d,q,clock);
    
    // Module arguments
    input wire  [11:0] d;
    output reg  [11:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 12'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$shade$1$row_q$3
module top$pipeline$shade$1$shaded_q$0(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$shaded_q$0
module top$pipeline$shade$1$shaded_q$1(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$shaded_q$1
module top$pipeline$shade$1$shaded_q$2(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$shaded_q$2
module top$pipeline$shade$1$specular_q(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$specular_q
module top$pipeline$shade$1$valid_q$0(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$valid_q$0
module top$pipeline$shade$1$valid_q$1(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$valid_q$1
module top$pipeline$shade$1$valid_q$10(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$valid_q$10
module top$pipeline$shade$1$valid_q$11(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$valid_q$11
module top$pipeline$shade$1$valid_q$12(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$valid_q$12
module top$pipeline$shade$1$valid_q$13(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$valid_q$13
module top$pipeline$shade$1$valid_q$14(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$valid_q$14
module top$pipeline$shade$1$valid_q$2(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$valid_q$2
module top$pipeline$shade$1$valid_q$3(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$valid_q$3
module top$pipeline$shade$1$valid_q$4(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$valid_q$4
module top$pipeline$shade$1$valid_q$5(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$valid_q$5
module top$pipeline$shade$1$valid_q$6(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$valid_q$6
module top$pipeline$shade$1$valid_q$7(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$valid_q$7
module top$pipeline$shade$1$valid_q$8(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$valid_q$8
module top$pipeline$shade$1$valid_q$9(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$valid_q$9
module top$pipeline$shade$1$value_q$0(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$value_q$0
module top$pipeline$shade$1$value_q$1(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$value_q$1
module top$pipeline$shade$1$value_q$10(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$value_q$10
module top$pipeline$shade$1$value_q$11(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$value_q$11
module top$pipeline$shade$1$value_q$12(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$value_q$12
module top$pipeline$shade$1$value_q$13(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$value_q$13
module top$pipeline$shade$1$value_q$2(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$value_q$2
module top$pipeline$shade$1$value_q$3(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$value_q$3
module top$pipeline$shade$1$value_q$4(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$value_q$4
module top$pipeline$shade$1$value_q$5(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$value_q$5
module top$pipeline$shade$1$value_q$6(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$value_q$6
module top$pipeline$shade$1$value_q$7(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$value_q$7
module top$pipeline$shade$1$value_q$8(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$value_q$8
module top$pipeline$shade$1$value_q$9(d,q,clock);
    
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
          
endmodule // top$pipeline$shade$1$value_q$9
