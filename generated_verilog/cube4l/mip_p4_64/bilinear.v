module top$lanes$0$bilinear(clock,c00$0,c00$1,c00$2,c00$3,c10$0,c10$1,c10$2,c10$3,c01$0,c01$1,c01$2,c01$3,c11$0,c11$1,c11$2,c11$3,wx,wy,out$0,out$1,out$2,out$3);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] c00$0;
    input wire  [31:0] c00$1;
    input wire  [31:0] c00$2;
    input wire  [31:0] c00$3;
    input wire  [31:0] c10$0;
    input wire  [31:0] c10$1;
    input wire  [31:0] c10$2;
    input wire  [31:0] c10$3;
    input wire  [31:0] c01$0;
    input wire  [31:0] c01$1;
    input wire  [31:0] c01$2;
    input wire  [31:0] c01$3;
    input wire  [31:0] c11$0;
    input wire  [31:0] c11$1;
    input wire  [31:0] c11$2;
    input wire  [31:0] c11$3;
    input wire  [15:0] wx;
    input wire  [15:0] wy;
    output reg  [31:0] out$0;
    output reg  [31:0] out$1;
    output reg  [31:0] out$2;
    output reg  [31:0] out$3;
    
    // Stub signals
    reg  [15:0] wx_q$0$d;
    wire  [15:0] wx_q$0$q;
    reg  wx_q$0$clock;
    reg  [15:0] wx_q$1$d;
    wire  [15:0] wx_q$1$q;
    reg  wx_q$1$clock;
    reg  [15:0] wx_q$2$d;
    wire  [15:0] wx_q$2$q;
    reg  wx_q$2$clock;
    reg  [15:0] wx_q$3$d;
    wire  [15:0] wx_q$3$q;
    reg  wx_q$3$clock;
    reg  [15:0] wy_q$0$d;
    wire  [15:0] wy_q$0$q;
    reg  wy_q$0$clock;
    reg  [15:0] wy_q$1$d;
    wire  [15:0] wy_q$1$q;
    reg  wy_q$1$clock;
    reg  [15:0] wy_q$2$d;
    wire  [15:0] wy_q$2$q;
    reg  wy_q$2$clock;
    reg  [15:0] wy_last$0$d;
    wire  [15:0] wy_last$0$q;
    reg  wy_last$0$clock;
    reg  [15:0] wy_last$1$d;
    wire  [15:0] wy_last$1$q;
    reg  wy_last$1$clock;
    reg  [15:0] wy_last$2$d;
    wire  [15:0] wy_last$2$q;
    reg  wy_last$2$clock;
    reg  [15:0] wy_last$3$d;
    wire  [15:0] wy_last$3$q;
    reg  wy_last$3$clock;
    reg  ch$0$clock;
    reg  [31:0] ch$0$c00;
    reg  [31:0] ch$0$c10;
    reg  [31:0] ch$0$c01;
    reg  [31:0] ch$0$c11;
    reg  [15:0] ch$0$wx;
    reg  [15:0] ch$0$wy;
    wire  [31:0] ch$0$y;
    reg  ch$1$clock;
    reg  [31:0] ch$1$c00;
    reg  [31:0] ch$1$c10;
    reg  [31:0] ch$1$c01;
    reg  [31:0] ch$1$c11;
    reg  [15:0] ch$1$wx;
    reg  [15:0] ch$1$wy;
    wire  [31:0] ch$1$y;
    reg  ch$2$clock;
    reg  [31:0] ch$2$c00;
    reg  [31:0] ch$2$c10;
    reg  [31:0] ch$2$c01;
    reg  [31:0] ch$2$c11;
    reg  [15:0] ch$2$wx;
    reg  [15:0] ch$2$wy;
    wire  [31:0] ch$2$y;
    reg  ch$3$clock;
    reg  [31:0] ch$3$c00;
    reg  [31:0] ch$3$c10;
    reg  [31:0] ch$3$c01;
    reg  [31:0] ch$3$c11;
    reg  [15:0] ch$3$wx;
    reg  [15:0] ch$3$wy;
    wire  [31:0] ch$3$y;
    
    // Sub module instances
    top$lanes$0$bilinear$wx_q$0 wx_q$0(
        .d(wx_q$0$d),
        .q(wx_q$0$q),
        .clock(wx_q$0$clock)
    );
    top$lanes$0$bilinear$wx_q$1 wx_q$1(
        .d(wx_q$1$d),
        .q(wx_q$1$q),
        .clock(wx_q$1$clock)
    );
    top$lanes$0$bilinear$wx_q$2 wx_q$2(
        .d(wx_q$2$d),
        .q(wx_q$2$q),
        .clock(wx_q$2$clock)
    );
    top$lanes$0$bilinear$wx_q$3 wx_q$3(
        .d(wx_q$3$d),
        .q(wx_q$3$q),
        .clock(wx_q$3$clock)
    );
    top$lanes$0$bilinear$wy_q$0 wy_q$0(
        .d(wy_q$0$d),
        .q(wy_q$0$q),
        .clock(wy_q$0$clock)
    );
    top$lanes$0$bilinear$wy_q$1 wy_q$1(
        .d(wy_q$1$d),
        .q(wy_q$1$q),
        .clock(wy_q$1$clock)
    );
    top$lanes$0$bilinear$wy_q$2 wy_q$2(
        .d(wy_q$2$d),
        .q(wy_q$2$q),
        .clock(wy_q$2$clock)
    );
    top$lanes$0$bilinear$wy_last$0 wy_last$0(
        .d(wy_last$0$d),
        .q(wy_last$0$q),
        .clock(wy_last$0$clock)
    );
    top$lanes$0$bilinear$wy_last$1 wy_last$1(
        .d(wy_last$1$d),
        .q(wy_last$1$q),
        .clock(wy_last$1$clock)
    );
    top$lanes$0$bilinear$wy_last$2 wy_last$2(
        .d(wy_last$2$d),
        .q(wy_last$2$q),
        .clock(wy_last$2$clock)
    );
    top$lanes$0$bilinear$wy_last$3 wy_last$3(
        .d(wy_last$3$d),
        .q(wy_last$3$q),
        .clock(wy_last$3$clock)
    );
    top$lanes$0$bilinear$ch$0 ch$0(
        .clock(ch$0$clock),
        .c00(ch$0$c00),
        .c10(ch$0$c10),
        .c01(ch$0$c01),
        .c11(ch$0$c11),
        .wx(ch$0$wx),
        .wy(ch$0$wy),
        .y(ch$0$y)
    );
    top$lanes$0$bilinear$ch$1 ch$1(
        .clock(ch$1$clock),
        .c00(ch$1$c00),
        .c10(ch$1$c10),
        .c01(ch$1$c01),
        .c11(ch$1$c11),
        .wx(ch$1$wx),
        .wy(ch$1$wy),
        .y(ch$1$y)
    );
    top$lanes$0$bilinear$ch$2 ch$2(
        .clock(ch$2$clock),
        .c00(ch$2$c00),
        .c10(ch$2$c10),
        .c01(ch$2$c01),
        .c11(ch$2$c11),
        .wx(ch$2$wx),
        .wy(ch$2$wy),
        .y(ch$2$y)
    );
    top$lanes$0$bilinear$ch$3 ch$3(
        .clock(ch$3$clock),
        .c00(ch$3$c00),
        .c10(ch$3$c10),
        .c01(ch$3$c01),
        .c11(ch$3$c11),
        .wx(ch$3$wx),
        .wy(ch$3$wy),
        .y(ch$3$y)
    );
    
    // Update code
    always @(*) begin
        wy_q$0$clock = clock;
        wy_q$1$clock = clock;
        wy_q$2$clock = clock;
        wy_q$0$d = wy;
        wy_q$1$d = wy_q$0$q;
        wy_q$2$d = wy_q$1$q;
        wx_q$0$clock = clock;
        wx_q$0$d = wx;
        wy_last$0$clock = clock;
        wy_last$0$d = wy_q$2$q;
        ch$0$clock = clock;
        ch$0$c00 = c00$0;
        ch$0$c10 = c10$0;
        ch$0$c01 = c01$0;
        ch$0$c11 = c11$0;
        ch$0$wx = wx_q$0$q;
        ch$0$wy = wy_last$0$q;
        out$0 = ch$0$y;
        wx_q$1$clock = clock;
        wx_q$1$d = wx;
        wy_last$1$clock = clock;
        wy_last$1$d = wy_q$2$q;
        ch$1$clock = clock;
        ch$1$c00 = c00$1;
        ch$1$c10 = c10$1;
        ch$1$c01 = c01$1;
        ch$1$c11 = c11$1;
        ch$1$wx = wx_q$1$q;
        ch$1$wy = wy_last$1$q;
        out$1 = ch$1$y;
        wx_q$2$clock = clock;
        wx_q$2$d = wx;
        wy_last$2$clock = clock;
        wy_last$2$d = wy_q$2$q;
        ch$2$clock = clock;
        ch$2$c00 = c00$2;
        ch$2$c10 = c10$2;
        ch$2$c01 = c01$2;
        ch$2$c11 = c11$2;
        ch$2$wx = wx_q$2$q;
        ch$2$wy = wy_last$2$q;
        out$2 = ch$2$y;
        wx_q$3$clock = clock;
        wx_q$3$d = wx;
        wy_last$3$clock = clock;
        wy_last$3$d = wy_q$2$q;
        ch$3$clock = clock;
        ch$3$c00 = c00$3;
        ch$3$c10 = c10$3;
        ch$3$c01 = c01$3;
        ch$3$c11 = c11$3;
        ch$3$wx = wx_q$3$q;
        ch$3$wy = wy_last$3$q;
        out$3 = ch$3$y;
    end
    
endmodule // top$lanes$0$bilinear
module top$lanes$0$bilinear$ch$0(clock,c00,c10,c01,c11,wx,wy,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] c00;
    input wire  [31:0] c10;
    input wire  [31:0] c01;
    input wire  [31:0] c11;
    input wire  [15:0] wx;
    input wire  [15:0] wy;
    output reg  [31:0] y;
    
    // Stub signals
    reg  top$clock;
    reg  [31:0] top$a;
    reg  [31:0] top$b;
    reg  [15:0] top$w;
    wire  [31:0] top$y;
    reg  bottom$clock;
    reg  [31:0] bottom$a;
    reg  [31:0] bottom$b;
    reg  [15:0] bottom$w;
    wire  [31:0] bottom$y;
    reg  vertical$clock;
    reg  [31:0] vertical$a;
    reg  [31:0] vertical$b;
    reg  [15:0] vertical$w;
    wire  [31:0] vertical$y;
    reg  [31:0] cells_q$0$d;
    wire  [31:0] cells_q$0$q;
    reg  cells_q$0$clock;
    reg  [31:0] cells_q$1$d;
    wire  [31:0] cells_q$1$q;
    reg  cells_q$1$clock;
    reg  [31:0] cells_q$2$d;
    wire  [31:0] cells_q$2$q;
    reg  cells_q$2$clock;
    reg  [31:0] cells_q$3$d;
    wire  [31:0] cells_q$3$q;
    reg  cells_q$3$clock;
    
    // Sub module instances
    top$lanes$0$bilinear$ch$0$top top(
        .clock(top$clock),
        .a(top$a),
        .b(top$b),
        .w(top$w),
        .y(top$y)
    );
    top$lanes$0$bilinear$ch$0$bottom bottom(
        .clock(bottom$clock),
        .a(bottom$a),
        .b(bottom$b),
        .w(bottom$w),
        .y(bottom$y)
    );
    top$lanes$0$bilinear$ch$0$vertical vertical(
        .clock(vertical$clock),
        .a(vertical$a),
        .b(vertical$b),
        .w(vertical$w),
        .y(vertical$y)
    );
    top$lanes$0$bilinear$ch$0$cells_q$0 cells_q$0(
        .d(cells_q$0$d),
        .q(cells_q$0$q),
        .clock(cells_q$0$clock)
    );
    top$lanes$0$bilinear$ch$0$cells_q$1 cells_q$1(
        .d(cells_q$1$d),
        .q(cells_q$1$q),
        .clock(cells_q$1$clock)
    );
    top$lanes$0$bilinear$ch$0$cells_q$2 cells_q$2(
        .d(cells_q$2$d),
        .q(cells_q$2$q),
        .clock(cells_q$2$clock)
    );
    top$lanes$0$bilinear$ch$0$cells_q$3 cells_q$3(
        .d(cells_q$3$d),
        .q(cells_q$3$q),
        .clock(cells_q$3$clock)
    );
    
    // Update code
    always @(*) begin
        cells_q$0$clock = clock;
        cells_q$1$clock = clock;
        cells_q$2$clock = clock;
        cells_q$3$clock = clock;
        top$clock = clock;
        bottom$clock = clock;
        vertical$clock = clock;
        cells_q$0$d = c00;
        cells_q$1$d = c10;
        cells_q$2$d = c01;
        cells_q$3$d = c11;
        top$a = cells_q$0$q;
        top$b = cells_q$1$q;
        top$w = wx;
        bottom$a = cells_q$2$q;
        bottom$b = cells_q$3$q;
        bottom$w = wx;
        vertical$a = top$y;
        vertical$b = bottom$y;
        vertical$w = wy;
        y = vertical$y;
    end
    
endmodule // top$lanes$0$bilinear$ch$0
module top$lanes$0$bilinear$ch$0$bottom(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$lanes$0$bilinear$ch$0$bottom$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$lanes$0$bilinear$ch$0$bottom$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$lanes$0$bilinear$ch$0$bottom$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$lanes$0$bilinear$ch$0$bottom$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$lanes$0$bilinear$ch$0$bottom$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$lanes$0$bilinear$ch$0$bottom$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$lanes$0$bilinear$ch$0$bottom$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$lanes$0$bilinear$ch$0$bottom$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$lanes$0$bilinear$ch$0$bottom$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$lanes$0$bilinear$ch$0$bottom
module top$lanes$0$bilinear$ch$0$bottom$a_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$0$bottom$a_q
module top$lanes$0$bilinear$ch$0$bottom$a_q2(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$0$bottom$a_q2
module top$lanes$0$bilinear$ch$0$bottom$diff_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$0$bottom$diff_q
module top$lanes$0$bilinear$ch$0$bottom$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$lanes$0$bilinear$ch$0$bottom$narrow
module top$lanes$0$bilinear$ch$0$bottom$prod_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$0$bottom$prod_q
module top$lanes$0$bilinear$ch$0$bottom$up_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$0$bottom$up_q
module top$lanes$0$bilinear$ch$0$bottom$up_q2(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$0$bottom$up_q2
module top$lanes$0$bilinear$ch$0$bottom$w_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$0$bottom$w_q
module top$lanes$0$bilinear$ch$0$bottom$y_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$0$bottom$y_q
module top$lanes$0$bilinear$ch$0$cells_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$0$cells_q$0
module top$lanes$0$bilinear$ch$0$cells_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$0$cells_q$1
module top$lanes$0$bilinear$ch$0$cells_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$0$cells_q$2
module top$lanes$0$bilinear$ch$0$cells_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$0$cells_q$3
module top$lanes$0$bilinear$ch$0$top(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$lanes$0$bilinear$ch$0$top$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$lanes$0$bilinear$ch$0$top$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$lanes$0$bilinear$ch$0$top$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$lanes$0$bilinear$ch$0$top$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$lanes$0$bilinear$ch$0$top$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$lanes$0$bilinear$ch$0$top$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$lanes$0$bilinear$ch$0$top$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$lanes$0$bilinear$ch$0$top$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$lanes$0$bilinear$ch$0$top$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$lanes$0$bilinear$ch$0$top
module top$lanes$0$bilinear$ch$0$top$a_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$0$top$a_q
module top$lanes$0$bilinear$ch$0$top$a_q2(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$0$top$a_q2
module top$lanes$0$bilinear$ch$0$top$diff_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$0$top$diff_q
module top$lanes$0$bilinear$ch$0$top$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$lanes$0$bilinear$ch$0$top$narrow
module top$lanes$0$bilinear$ch$0$top$prod_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$0$top$prod_q
module top$lanes$0$bilinear$ch$0$top$up_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$0$top$up_q
module top$lanes$0$bilinear$ch$0$top$up_q2(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$0$top$up_q2
module top$lanes$0$bilinear$ch$0$top$w_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$0$top$w_q
module top$lanes$0$bilinear$ch$0$top$y_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$0$top$y_q
module top$lanes$0$bilinear$ch$0$vertical(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$lanes$0$bilinear$ch$0$vertical$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$lanes$0$bilinear$ch$0$vertical$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$lanes$0$bilinear$ch$0$vertical$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$lanes$0$bilinear$ch$0$vertical$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$lanes$0$bilinear$ch$0$vertical$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$lanes$0$bilinear$ch$0$vertical$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$lanes$0$bilinear$ch$0$vertical$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$lanes$0$bilinear$ch$0$vertical$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$lanes$0$bilinear$ch$0$vertical$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$lanes$0$bilinear$ch$0$vertical
module top$lanes$0$bilinear$ch$0$vertical$a_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$0$vertical$a_q
module top$lanes$0$bilinear$ch$0$vertical$a_q2(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$0$vertical$a_q2
module top$lanes$0$bilinear$ch$0$vertical$diff_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$0$vertical$diff_q
module top$lanes$0$bilinear$ch$0$vertical$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$lanes$0$bilinear$ch$0$vertical$narrow
module top$lanes$0$bilinear$ch$0$vertical$prod_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$0$vertical$prod_q
module top$lanes$0$bilinear$ch$0$vertical$up_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$0$vertical$up_q
module top$lanes$0$bilinear$ch$0$vertical$up_q2(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$0$vertical$up_q2
module top$lanes$0$bilinear$ch$0$vertical$w_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$0$vertical$w_q
module top$lanes$0$bilinear$ch$0$vertical$y_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$0$vertical$y_q
module top$lanes$0$bilinear$ch$1(clock,c00,c10,c01,c11,wx,wy,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] c00;
    input wire  [31:0] c10;
    input wire  [31:0] c01;
    input wire  [31:0] c11;
    input wire  [15:0] wx;
    input wire  [15:0] wy;
    output reg  [31:0] y;
    
    // Stub signals
    reg  top$clock;
    reg  [31:0] top$a;
    reg  [31:0] top$b;
    reg  [15:0] top$w;
    wire  [31:0] top$y;
    reg  bottom$clock;
    reg  [31:0] bottom$a;
    reg  [31:0] bottom$b;
    reg  [15:0] bottom$w;
    wire  [31:0] bottom$y;
    reg  vertical$clock;
    reg  [31:0] vertical$a;
    reg  [31:0] vertical$b;
    reg  [15:0] vertical$w;
    wire  [31:0] vertical$y;
    reg  [31:0] cells_q$0$d;
    wire  [31:0] cells_q$0$q;
    reg  cells_q$0$clock;
    reg  [31:0] cells_q$1$d;
    wire  [31:0] cells_q$1$q;
    reg  cells_q$1$clock;
    reg  [31:0] cells_q$2$d;
    wire  [31:0] cells_q$2$q;
    reg  cells_q$2$clock;
    reg  [31:0] cells_q$3$d;
    wire  [31:0] cells_q$3$q;
    reg  cells_q$3$clock;
    
    // Sub module instances
    top$lanes$0$bilinear$ch$1$top top(
        .clock(top$clock),
        .a(top$a),
        .b(top$b),
        .w(top$w),
        .y(top$y)
    );
    top$lanes$0$bilinear$ch$1$bottom bottom(
        .clock(bottom$clock),
        .a(bottom$a),
        .b(bottom$b),
        .w(bottom$w),
        .y(bottom$y)
    );
    top$lanes$0$bilinear$ch$1$vertical vertical(
        .clock(vertical$clock),
        .a(vertical$a),
        .b(vertical$b),
        .w(vertical$w),
        .y(vertical$y)
    );
    top$lanes$0$bilinear$ch$1$cells_q$0 cells_q$0(
        .d(cells_q$0$d),
        .q(cells_q$0$q),
        .clock(cells_q$0$clock)
    );
    top$lanes$0$bilinear$ch$1$cells_q$1 cells_q$1(
        .d(cells_q$1$d),
        .q(cells_q$1$q),
        .clock(cells_q$1$clock)
    );
    top$lanes$0$bilinear$ch$1$cells_q$2 cells_q$2(
        .d(cells_q$2$d),
        .q(cells_q$2$q),
        .clock(cells_q$2$clock)
    );
    top$lanes$0$bilinear$ch$1$cells_q$3 cells_q$3(
        .d(cells_q$3$d),
        .q(cells_q$3$q),
        .clock(cells_q$3$clock)
    );
    
    // Update code
    always @(*) begin
        cells_q$0$clock = clock;
        cells_q$1$clock = clock;
        cells_q$2$clock = clock;
        cells_q$3$clock = clock;
        top$clock = clock;
        bottom$clock = clock;
        vertical$clock = clock;
        cells_q$0$d = c00;
        cells_q$1$d = c10;
        cells_q$2$d = c01;
        cells_q$3$d = c11;
        top$a = cells_q$0$q;
        top$b = cells_q$1$q;
        top$w = wx;
        bottom$a = cells_q$2$q;
        bottom$b = cells_q$3$q;
        bottom$w = wx;
        vertical$a = top$y;
        vertical$b = bottom$y;
        vertical$w = wy;
        y = vertical$y;
    end
    
endmodule // top$lanes$0$bilinear$ch$1
module top$lanes$0$bilinear$ch$1$bottom(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$lanes$0$bilinear$ch$1$bottom$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$lanes$0$bilinear$ch$1$bottom$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$lanes$0$bilinear$ch$1$bottom$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$lanes$0$bilinear$ch$1$bottom$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$lanes$0$bilinear$ch$1$bottom$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$lanes$0$bilinear$ch$1$bottom$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$lanes$0$bilinear$ch$1$bottom$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$lanes$0$bilinear$ch$1$bottom$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$lanes$0$bilinear$ch$1$bottom$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$lanes$0$bilinear$ch$1$bottom
module top$lanes$0$bilinear$ch$1$bottom$a_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$1$bottom$a_q
module top$lanes$0$bilinear$ch$1$bottom$a_q2(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$1$bottom$a_q2
module top$lanes$0$bilinear$ch$1$bottom$diff_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$1$bottom$diff_q
module top$lanes$0$bilinear$ch$1$bottom$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$lanes$0$bilinear$ch$1$bottom$narrow
module top$lanes$0$bilinear$ch$1$bottom$prod_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$1$bottom$prod_q
module top$lanes$0$bilinear$ch$1$bottom$up_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$1$bottom$up_q
module top$lanes$0$bilinear$ch$1$bottom$up_q2(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$1$bottom$up_q2
module top$lanes$0$bilinear$ch$1$bottom$w_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$1$bottom$w_q
module top$lanes$0$bilinear$ch$1$bottom$y_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$1$bottom$y_q
module top$lanes$0$bilinear$ch$1$cells_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$1$cells_q$0
module top$lanes$0$bilinear$ch$1$cells_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$1$cells_q$1
module top$lanes$0$bilinear$ch$1$cells_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$1$cells_q$2
module top$lanes$0$bilinear$ch$1$cells_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$1$cells_q$3
module top$lanes$0$bilinear$ch$1$top(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$lanes$0$bilinear$ch$1$top$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$lanes$0$bilinear$ch$1$top$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$lanes$0$bilinear$ch$1$top$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$lanes$0$bilinear$ch$1$top$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$lanes$0$bilinear$ch$1$top$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$lanes$0$bilinear$ch$1$top$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$lanes$0$bilinear$ch$1$top$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$lanes$0$bilinear$ch$1$top$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$lanes$0$bilinear$ch$1$top$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$lanes$0$bilinear$ch$1$top
module top$lanes$0$bilinear$ch$1$top$a_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$1$top$a_q
module top$lanes$0$bilinear$ch$1$top$a_q2(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$1$top$a_q2
module top$lanes$0$bilinear$ch$1$top$diff_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$1$top$diff_q
module top$lanes$0$bilinear$ch$1$top$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$lanes$0$bilinear$ch$1$top$narrow
module top$lanes$0$bilinear$ch$1$top$prod_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$1$top$prod_q
module top$lanes$0$bilinear$ch$1$top$up_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$1$top$up_q
module top$lanes$0$bilinear$ch$1$top$up_q2(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$1$top$up_q2
module top$lanes$0$bilinear$ch$1$top$w_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$1$top$w_q
module top$lanes$0$bilinear$ch$1$top$y_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$1$top$y_q
module top$lanes$0$bilinear$ch$1$vertical(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$lanes$0$bilinear$ch$1$vertical$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$lanes$0$bilinear$ch$1$vertical$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$lanes$0$bilinear$ch$1$vertical$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$lanes$0$bilinear$ch$1$vertical$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$lanes$0$bilinear$ch$1$vertical$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$lanes$0$bilinear$ch$1$vertical$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$lanes$0$bilinear$ch$1$vertical$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$lanes$0$bilinear$ch$1$vertical$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$lanes$0$bilinear$ch$1$vertical$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$lanes$0$bilinear$ch$1$vertical
module top$lanes$0$bilinear$ch$1$vertical$a_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$1$vertical$a_q
module top$lanes$0$bilinear$ch$1$vertical$a_q2(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$1$vertical$a_q2
module top$lanes$0$bilinear$ch$1$vertical$diff_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$1$vertical$diff_q
module top$lanes$0$bilinear$ch$1$vertical$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$lanes$0$bilinear$ch$1$vertical$narrow
module top$lanes$0$bilinear$ch$1$vertical$prod_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$1$vertical$prod_q
module top$lanes$0$bilinear$ch$1$vertical$up_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$1$vertical$up_q
module top$lanes$0$bilinear$ch$1$vertical$up_q2(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$1$vertical$up_q2
module top$lanes$0$bilinear$ch$1$vertical$w_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$1$vertical$w_q
module top$lanes$0$bilinear$ch$1$vertical$y_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$1$vertical$y_q
module top$lanes$0$bilinear$ch$2(clock,c00,c10,c01,c11,wx,wy,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] c00;
    input wire  [31:0] c10;
    input wire  [31:0] c01;
    input wire  [31:0] c11;
    input wire  [15:0] wx;
    input wire  [15:0] wy;
    output reg  [31:0] y;
    
    // Stub signals
    reg  top$clock;
    reg  [31:0] top$a;
    reg  [31:0] top$b;
    reg  [15:0] top$w;
    wire  [31:0] top$y;
    reg  bottom$clock;
    reg  [31:0] bottom$a;
    reg  [31:0] bottom$b;
    reg  [15:0] bottom$w;
    wire  [31:0] bottom$y;
    reg  vertical$clock;
    reg  [31:0] vertical$a;
    reg  [31:0] vertical$b;
    reg  [15:0] vertical$w;
    wire  [31:0] vertical$y;
    reg  [31:0] cells_q$0$d;
    wire  [31:0] cells_q$0$q;
    reg  cells_q$0$clock;
    reg  [31:0] cells_q$1$d;
    wire  [31:0] cells_q$1$q;
    reg  cells_q$1$clock;
    reg  [31:0] cells_q$2$d;
    wire  [31:0] cells_q$2$q;
    reg  cells_q$2$clock;
    reg  [31:0] cells_q$3$d;
    wire  [31:0] cells_q$3$q;
    reg  cells_q$3$clock;
    
    // Sub module instances
    top$lanes$0$bilinear$ch$2$top top(
        .clock(top$clock),
        .a(top$a),
        .b(top$b),
        .w(top$w),
        .y(top$y)
    );
    top$lanes$0$bilinear$ch$2$bottom bottom(
        .clock(bottom$clock),
        .a(bottom$a),
        .b(bottom$b),
        .w(bottom$w),
        .y(bottom$y)
    );
    top$lanes$0$bilinear$ch$2$vertical vertical(
        .clock(vertical$clock),
        .a(vertical$a),
        .b(vertical$b),
        .w(vertical$w),
        .y(vertical$y)
    );
    top$lanes$0$bilinear$ch$2$cells_q$0 cells_q$0(
        .d(cells_q$0$d),
        .q(cells_q$0$q),
        .clock(cells_q$0$clock)
    );
    top$lanes$0$bilinear$ch$2$cells_q$1 cells_q$1(
        .d(cells_q$1$d),
        .q(cells_q$1$q),
        .clock(cells_q$1$clock)
    );
    top$lanes$0$bilinear$ch$2$cells_q$2 cells_q$2(
        .d(cells_q$2$d),
        .q(cells_q$2$q),
        .clock(cells_q$2$clock)
    );
    top$lanes$0$bilinear$ch$2$cells_q$3 cells_q$3(
        .d(cells_q$3$d),
        .q(cells_q$3$q),
        .clock(cells_q$3$clock)
    );
    
    // Update code
    always @(*) begin
        cells_q$0$clock = clock;
        cells_q$1$clock = clock;
        cells_q$2$clock = clock;
        cells_q$3$clock = clock;
        top$clock = clock;
        bottom$clock = clock;
        vertical$clock = clock;
        cells_q$0$d = c00;
        cells_q$1$d = c10;
        cells_q$2$d = c01;
        cells_q$3$d = c11;
        top$a = cells_q$0$q;
        top$b = cells_q$1$q;
        top$w = wx;
        bottom$a = cells_q$2$q;
        bottom$b = cells_q$3$q;
        bottom$w = wx;
        vertical$a = top$y;
        vertical$b = bottom$y;
        vertical$w = wy;
        y = vertical$y;
    end
    
endmodule // top$lanes$0$bilinear$ch$2
module top$lanes$0$bilinear$ch$2$bottom(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$lanes$0$bilinear$ch$2$bottom$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$lanes$0$bilinear$ch$2$bottom$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$lanes$0$bilinear$ch$2$bottom$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$lanes$0$bilinear$ch$2$bottom$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$lanes$0$bilinear$ch$2$bottom$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$lanes$0$bilinear$ch$2$bottom$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$lanes$0$bilinear$ch$2$bottom$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$lanes$0$bilinear$ch$2$bottom$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$lanes$0$bilinear$ch$2$bottom$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$lanes$0$bilinear$ch$2$bottom
module top$lanes$0$bilinear$ch$2$bottom$a_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$2$bottom$a_q
module top$lanes$0$bilinear$ch$2$bottom$a_q2(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$2$bottom$a_q2
module top$lanes$0$bilinear$ch$2$bottom$diff_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$2$bottom$diff_q
module top$lanes$0$bilinear$ch$2$bottom$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$lanes$0$bilinear$ch$2$bottom$narrow
module top$lanes$0$bilinear$ch$2$bottom$prod_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$2$bottom$prod_q
module top$lanes$0$bilinear$ch$2$bottom$up_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$2$bottom$up_q
module top$lanes$0$bilinear$ch$2$bottom$up_q2(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$2$bottom$up_q2
module top$lanes$0$bilinear$ch$2$bottom$w_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$2$bottom$w_q
module top$lanes$0$bilinear$ch$2$bottom$y_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$2$bottom$y_q
module top$lanes$0$bilinear$ch$2$cells_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$2$cells_q$0
module top$lanes$0$bilinear$ch$2$cells_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$2$cells_q$1
module top$lanes$0$bilinear$ch$2$cells_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$2$cells_q$2
module top$lanes$0$bilinear$ch$2$cells_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$2$cells_q$3
module top$lanes$0$bilinear$ch$2$top(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$lanes$0$bilinear$ch$2$top$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$lanes$0$bilinear$ch$2$top$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$lanes$0$bilinear$ch$2$top$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$lanes$0$bilinear$ch$2$top$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$lanes$0$bilinear$ch$2$top$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$lanes$0$bilinear$ch$2$top$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$lanes$0$bilinear$ch$2$top$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$lanes$0$bilinear$ch$2$top$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$lanes$0$bilinear$ch$2$top$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$lanes$0$bilinear$ch$2$top
module top$lanes$0$bilinear$ch$2$top$a_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$2$top$a_q
module top$lanes$0$bilinear$ch$2$top$a_q2(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$2$top$a_q2
module top$lanes$0$bilinear$ch$2$top$diff_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$2$top$diff_q
module top$lanes$0$bilinear$ch$2$top$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$lanes$0$bilinear$ch$2$top$narrow
module top$lanes$0$bilinear$ch$2$top$prod_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$2$top$prod_q
module top$lanes$0$bilinear$ch$2$top$up_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$2$top$up_q
module top$lanes$0$bilinear$ch$2$top$up_q2(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$2$top$up_q2
module top$lanes$0$bilinear$ch$2$top$w_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$2$top$w_q
module top$lanes$0$bilinear$ch$2$top$y_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$2$top$y_q
module top$lanes$0$bilinear$ch$2$vertical(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$lanes$0$bilinear$ch$2$vertical$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$lanes$0$bilinear$ch$2$vertical$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$lanes$0$bilinear$ch$2$vertical$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$lanes$0$bilinear$ch$2$vertical$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$lanes$0$bilinear$ch$2$vertical$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$lanes$0$bilinear$ch$2$vertical$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$lanes$0$bilinear$ch$2$vertical$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$lanes$0$bilinear$ch$2$vertical$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$lanes$0$bilinear$ch$2$vertical$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$lanes$0$bilinear$ch$2$vertical
module top$lanes$0$bilinear$ch$2$vertical$a_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$2$vertical$a_q
module top$lanes$0$bilinear$ch$2$vertical$a_q2(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$2$vertical$a_q2
module top$lanes$0$bilinear$ch$2$vertical$diff_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$2$vertical$diff_q
module top$lanes$0$bilinear$ch$2$vertical$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$lanes$0$bilinear$ch$2$vertical$narrow
module top$lanes$0$bilinear$ch$2$vertical$prod_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$2$vertical$prod_q
module top$lanes$0$bilinear$ch$2$vertical$up_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$2$vertical$up_q
module top$lanes$0$bilinear$ch$2$vertical$up_q2(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$2$vertical$up_q2
module top$lanes$0$bilinear$ch$2$vertical$w_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$2$vertical$w_q
module top$lanes$0$bilinear$ch$2$vertical$y_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$2$vertical$y_q
module top$lanes$0$bilinear$ch$3(clock,c00,c10,c01,c11,wx,wy,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] c00;
    input wire  [31:0] c10;
    input wire  [31:0] c01;
    input wire  [31:0] c11;
    input wire  [15:0] wx;
    input wire  [15:0] wy;
    output reg  [31:0] y;
    
    // Stub signals
    reg  top$clock;
    reg  [31:0] top$a;
    reg  [31:0] top$b;
    reg  [15:0] top$w;
    wire  [31:0] top$y;
    reg  bottom$clock;
    reg  [31:0] bottom$a;
    reg  [31:0] bottom$b;
    reg  [15:0] bottom$w;
    wire  [31:0] bottom$y;
    reg  vertical$clock;
    reg  [31:0] vertical$a;
    reg  [31:0] vertical$b;
    reg  [15:0] vertical$w;
    wire  [31:0] vertical$y;
    reg  [31:0] cells_q$0$d;
    wire  [31:0] cells_q$0$q;
    reg  cells_q$0$clock;
    reg  [31:0] cells_q$1$d;
    wire  [31:0] cells_q$1$q;
    reg  cells_q$1$clock;
    reg  [31:0] cells_q$2$d;
    wire  [31:0] cells_q$2$q;
    reg  cells_q$2$clock;
    reg  [31:0] cells_q$3$d;
    wire  [31:0] cells_q$3$q;
    reg  cells_q$3$clock;
    
    // Sub module instances
    top$lanes$0$bilinear$ch$3$top top(
        .clock(top$clock),
        .a(top$a),
        .b(top$b),
        .w(top$w),
        .y(top$y)
    );
    top$lanes$0$bilinear$ch$3$bottom bottom(
        .clock(bottom$clock),
        .a(bottom$a),
        .b(bottom$b),
        .w(bottom$w),
        .y(bottom$y)
    );
    top$lanes$0$bilinear$ch$3$vertical vertical(
        .clock(vertical$clock),
        .a(vertical$a),
        .b(vertical$b),
        .w(vertical$w),
        .y(vertical$y)
    );
    top$lanes$0$bilinear$ch$3$cells_q$0 cells_q$0(
        .d(cells_q$0$d),
        .q(cells_q$0$q),
        .clock(cells_q$0$clock)
    );
    top$lanes$0$bilinear$ch$3$cells_q$1 cells_q$1(
        .d(cells_q$1$d),
        .q(cells_q$1$q),
        .clock(cells_q$1$clock)
    );
    top$lanes$0$bilinear$ch$3$cells_q$2 cells_q$2(
        .d(cells_q$2$d),
        .q(cells_q$2$q),
        .clock(cells_q$2$clock)
    );
    top$lanes$0$bilinear$ch$3$cells_q$3 cells_q$3(
        .d(cells_q$3$d),
        .q(cells_q$3$q),
        .clock(cells_q$3$clock)
    );
    
    // Update code
    always @(*) begin
        cells_q$0$clock = clock;
        cells_q$1$clock = clock;
        cells_q$2$clock = clock;
        cells_q$3$clock = clock;
        top$clock = clock;
        bottom$clock = clock;
        vertical$clock = clock;
        cells_q$0$d = c00;
        cells_q$1$d = c10;
        cells_q$2$d = c01;
        cells_q$3$d = c11;
        top$a = cells_q$0$q;
        top$b = cells_q$1$q;
        top$w = wx;
        bottom$a = cells_q$2$q;
        bottom$b = cells_q$3$q;
        bottom$w = wx;
        vertical$a = top$y;
        vertical$b = bottom$y;
        vertical$w = wy;
        y = vertical$y;
    end
    
endmodule // top$lanes$0$bilinear$ch$3
module top$lanes$0$bilinear$ch$3$bottom(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$lanes$0$bilinear$ch$3$bottom$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$lanes$0$bilinear$ch$3$bottom$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$lanes$0$bilinear$ch$3$bottom$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$lanes$0$bilinear$ch$3$bottom$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$lanes$0$bilinear$ch$3$bottom$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$lanes$0$bilinear$ch$3$bottom$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$lanes$0$bilinear$ch$3$bottom$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$lanes$0$bilinear$ch$3$bottom$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$lanes$0$bilinear$ch$3$bottom$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$lanes$0$bilinear$ch$3$bottom
module top$lanes$0$bilinear$ch$3$bottom$a_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$3$bottom$a_q
module top$lanes$0$bilinear$ch$3$bottom$a_q2(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$3$bottom$a_q2
module top$lanes$0$bilinear$ch$3$bottom$diff_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$3$bottom$diff_q
module top$lanes$0$bilinear$ch$3$bottom$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$lanes$0$bilinear$ch$3$bottom$narrow
module top$lanes$0$bilinear$ch$3$bottom$prod_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$3$bottom$prod_q
module top$lanes$0$bilinear$ch$3$bottom$up_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$3$bottom$up_q
module top$lanes$0$bilinear$ch$3$bottom$up_q2(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$3$bottom$up_q2
module top$lanes$0$bilinear$ch$3$bottom$w_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$3$bottom$w_q
module top$lanes$0$bilinear$ch$3$bottom$y_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$3$bottom$y_q
module top$lanes$0$bilinear$ch$3$cells_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$3$cells_q$0
module top$lanes$0$bilinear$ch$3$cells_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$3$cells_q$1
module top$lanes$0$bilinear$ch$3$cells_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$3$cells_q$2
module top$lanes$0$bilinear$ch$3$cells_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$3$cells_q$3
module top$lanes$0$bilinear$ch$3$top(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$lanes$0$bilinear$ch$3$top$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$lanes$0$bilinear$ch$3$top$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$lanes$0$bilinear$ch$3$top$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$lanes$0$bilinear$ch$3$top$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$lanes$0$bilinear$ch$3$top$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$lanes$0$bilinear$ch$3$top$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$lanes$0$bilinear$ch$3$top$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$lanes$0$bilinear$ch$3$top$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$lanes$0$bilinear$ch$3$top$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$lanes$0$bilinear$ch$3$top
module top$lanes$0$bilinear$ch$3$top$a_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$3$top$a_q
module top$lanes$0$bilinear$ch$3$top$a_q2(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$3$top$a_q2
module top$lanes$0$bilinear$ch$3$top$diff_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$3$top$diff_q
module top$lanes$0$bilinear$ch$3$top$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$lanes$0$bilinear$ch$3$top$narrow
module top$lanes$0$bilinear$ch$3$top$prod_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$3$top$prod_q
module top$lanes$0$bilinear$ch$3$top$up_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$3$top$up_q
module top$lanes$0$bilinear$ch$3$top$up_q2(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$3$top$up_q2
module top$lanes$0$bilinear$ch$3$top$w_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$3$top$w_q
module top$lanes$0$bilinear$ch$3$top$y_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$3$top$y_q
module top$lanes$0$bilinear$ch$3$vertical(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$lanes$0$bilinear$ch$3$vertical$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$lanes$0$bilinear$ch$3$vertical$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$lanes$0$bilinear$ch$3$vertical$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$lanes$0$bilinear$ch$3$vertical$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$lanes$0$bilinear$ch$3$vertical$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$lanes$0$bilinear$ch$3$vertical$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$lanes$0$bilinear$ch$3$vertical$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$lanes$0$bilinear$ch$3$vertical$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$lanes$0$bilinear$ch$3$vertical$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$lanes$0$bilinear$ch$3$vertical
module top$lanes$0$bilinear$ch$3$vertical$a_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$3$vertical$a_q
module top$lanes$0$bilinear$ch$3$vertical$a_q2(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$3$vertical$a_q2
module top$lanes$0$bilinear$ch$3$vertical$diff_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$3$vertical$diff_q
module top$lanes$0$bilinear$ch$3$vertical$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$lanes$0$bilinear$ch$3$vertical$narrow
module top$lanes$0$bilinear$ch$3$vertical$prod_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$3$vertical$prod_q
module top$lanes$0$bilinear$ch$3$vertical$up_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$3$vertical$up_q
module top$lanes$0$bilinear$ch$3$vertical$up_q2(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$3$vertical$up_q2
module top$lanes$0$bilinear$ch$3$vertical$w_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$3$vertical$w_q
module top$lanes$0$bilinear$ch$3$vertical$y_q(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$ch$3$vertical$y_q
module top$lanes$0$bilinear$wx_q$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$0$bilinear$wx_q$0
module top$lanes$0$bilinear$wx_q$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$0$bilinear$wx_q$1
module top$lanes$0$bilinear$wx_q$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$0$bilinear$wx_q$2
module top$lanes$0$bilinear$wx_q$3(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$0$bilinear$wx_q$3
module top$lanes$0$bilinear$wy_last$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$0$bilinear$wy_last$0
module top$lanes$0$bilinear$wy_last$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$0$bilinear$wy_last$1
module top$lanes$0$bilinear$wy_last$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$0$bilinear$wy_last$2
module top$lanes$0$bilinear$wy_last$3(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$0$bilinear$wy_last$3
module top$lanes$0$bilinear$wy_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$wy_q$0
module top$lanes$0$bilinear$wy_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$wy_q$1
module top$lanes$0$bilinear$wy_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$0$bilinear$wy_q$2
module top$lanes$1$bilinear(clock,c00$0,c00$1,c00$2,c00$3,c10$0,c10$1,c10$2,c10$3,c01$0,c01$1,c01$2,c01$3,c11$0,c11$1,c11$2,c11$3,wx,wy,out$0,out$1,out$2,out$3);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] c00$0;
    input wire  [31:0] c00$1;
    input wire  [31:0] c00$2;
    input wire  [31:0] c00$3;
    input wire  [31:0] c10$0;
    input wire  [31:0] c10$1;
    input wire  [31:0] c10$2;
    input wire  [31:0] c10$3;
    input wire  [31:0] c01$0;
    input wire  [31:0] c01$1;
    input wire  [31:0] c01$2;
    input wire  [31:0] c01$3;
    input wire  [31:0] c11$0;
    input wire  [31:0] c11$1;
    input wire  [31:0] c11$2;
    input wire  [31:0] c11$3;
    input wire  [15:0] wx;
    input wire  [15:0] wy;
    output reg  [31:0] out$0;
    output reg  [31:0] out$1;
    output reg  [31:0] out$2;
    output reg  [31:0] out$3;
    
    // Stub signals
    reg  [15:0] wx_q$0$d;
    wire  [15:0] wx_q$0$q;
    reg  wx_q$0$clock;
    reg  [15:0] wx_q$1$d;
    wire  [15:0] wx_q$1$q;
    reg  wx_q$1$clock;
    reg  [15:0] wx_q$2$d;
    wire  [15:0] wx_q$2$q;
    reg  wx_q$2$clock;
    reg  [15:0] wx_q$3$d;
    wire  [15:0] wx_q$3$q;
    reg  wx_q$3$clock;
    reg  [15:0] wy_q$0$d;
    wire  [15:0] wy_q$0$q;
    reg  wy_q$0$clock;
    reg  [15:0] wy_q$1$d;
    wire  [15:0] wy_q$1$q;
    reg  wy_q$1$clock;
    reg  [15:0] wy_q$2$d;
    wire  [15:0] wy_q$2$q;
    reg  wy_q$2$clock;
    reg  [15:0] wy_last$0$d;
    wire  [15:0] wy_last$0$q;
    reg  wy_last$0$clock;
    reg  [15:0] wy_last$1$d;
    wire  [15:0] wy_last$1$q;
    reg  wy_last$1$clock;
    reg  [15:0] wy_last$2$d;
    wire  [15:0] wy_last$2$q;
    reg  wy_last$2$clock;
    reg  [15:0] wy_last$3$d;
    wire  [15:0] wy_last$3$q;
    reg  wy_last$3$clock;
    reg  ch$0$clock;
    reg  [31:0] ch$0$c00;
    reg  [31:0] ch$0$c10;
    reg  [31:0] ch$0$c01;
    reg  [31:0] ch$0$c11;
    reg  [15:0] ch$0$wx;
    reg  [15:0] ch$0$wy;
    wire  [31:0] ch$0$y;
    reg  ch$1$clock;
    reg  [31:0] ch$1$c00;
    reg  [31:0] ch$1$c10;
    reg  [31:0] ch$1$c01;
    reg  [31:0] ch$1$c11;
    reg  [15:0] ch$1$wx;
    reg  [15:0] ch$1$wy;
    wire  [31:0] ch$1$y;
    reg  ch$2$clock;
    reg  [31:0] ch$2$c00;
    reg  [31:0] ch$2$c10;
    reg  [31:0] ch$2$c01;
    reg  [31:0] ch$2$c11;
    reg  [15:0] ch$2$wx;
    reg  [15:0] ch$2$wy;
    wire  [31:0] ch$2$y;
    reg  ch$3$clock;
    reg  [31:0] ch$3$c00;
    reg  [31:0] ch$3$c10;
    reg  [31:0] ch$3$c01;
    reg  [31:0] ch$3$c11;
    reg  [15:0] ch$3$wx;
    reg  [15:0] ch$3$wy;
    wire  [31:0] ch$3$y;
    
    // Sub module instances
    top$lanes$1$bilinear$wx_q$0 wx_q$0(
        .d(wx_q$0$d),
        .q(wx_q$0$q),
        .clock(wx_q$0$clock)
    );
    top$lanes$1$bilinear$wx_q$1 wx_q$1(
        .d(wx_q$1$d),
        .q(wx_q$1$q),
        .clock(wx_q$1$clock)
    );
    top$lanes$1$bilinear$wx_q$2 wx_q$2(
        .d(wx_q$2$d),
        .q(wx_q$2$q),
        .clock(wx_q$2$clock)
    );
    top$lanes$1$bilinear$wx_q$3 wx_q$3(
        .d(wx_q$3$d),
        .q(wx_q$3$q),
        .clock(wx_q$3$clock)
    );
    top$lanes$1$bilinear$wy_q$0 wy_q$0(
        .d(wy_q$0$d),
        .q(wy_q$0$q),
        .clock(wy_q$0$clock)
    );
    top$lanes$1$bilinear$wy_q$1 wy_q$1(
        .d(wy_q$1$d),
        .q(wy_q$1$q),
        .clock(wy_q$1$clock)
    );
    top$lanes$1$bilinear$wy_q$2 wy_q$2(
        .d(wy_q$2$d),
        .q(wy_q$2$q),
        .clock(wy_q$2$clock)
    );
    top$lanes$1$bilinear$wy_last$0 wy_last$0(
        .d(wy_last$0$d),
        .q(wy_last$0$q),
        .clock(wy_last$0$clock)
    );
    top$lanes$1$bilinear$wy_last$1 wy_last$1(
        .d(wy_last$1$d),
        .q(wy_last$1$q),
        .clock(wy_last$1$clock)
    );
    top$lanes$1$bilinear$wy_last$2 wy_last$2(
        .d(wy_last$2$d),
        .q(wy_last$2$q),
        .clock(wy_last$2$clock)
    );
    top$lanes$1$bilinear$wy_last$3 wy_last$3(
        .d(wy_last$3$d),
        .q(wy_last$3$q),
        .clock(wy_last$3$clock)
    );
    top$lanes$1$bilinear$ch$0 ch$0(
        .clock(ch$0$clock),
        .c00(ch$0$c00),
        .c10(ch$0$c10),
        .c01(ch$0$c01),
        .c11(ch$0$c11),
        .wx(ch$0$wx),
        .wy(ch$0$wy),
        .y(ch$0$y)
    );
    top$lanes$1$bilinear$ch$1 ch$1(
        .clock(ch$1$clock),
        .c00(ch$1$c00),
        .c10(ch$1$c10),
        .c01(ch$1$c01),
        .c11(ch$1$c11),
        .wx(ch$1$wx),
        .wy(ch$1$wy),
        .y(ch$1$y)
    );
    top$lanes$1$bilinear$ch$2 ch$2(
        .clock(ch$2$clock),
        .c00(ch$2$c00),
        .c10(ch$2$c10),
        .c01(ch$2$c01),
        .c11(ch$2$c11),
        .wx(ch$2$wx),
        .wy(ch$2$wy),
        .y(ch$2$y)
    );
    top$lanes$1$bilinear$ch$3 ch$3(
        .clock(ch$3$clock),
        .c00(ch$3$c00),
        .c10(ch$3$c10),
        .c01(ch$3$c01),
        .c11(ch$3$c11),
        .wx(ch$3$wx),
        .wy(ch$3$wy),
        .y(ch$3$y)
    );
    
    // Update code
    always @(*) begin
        wy_q$0$clock = clock;
        wy_q$1$clock = clock;
        wy_q$2$clock = clock;
        wy_q$0$d = wy;
        wy_q$1$d = wy_q$0$q;
        wy_q$2$d = wy_q$1$q;
        wx_q$0$clock = clock;
        wx_q$0$d = wx;
        wy_last$0$clock = clock;
        wy_last$0$d = wy_q$2$q;
        ch$0$clock = clock;
        ch$0$c00 = c00$0;
        ch$0$c10 = c10$0;
        ch$0$c01 = c01$0;
        ch$0$c11 = c11$0;
        ch$0$wx = wx_q$0$q;
        ch$0$wy = wy_last$0$q;
        out$0 = ch$0$y;
        wx_q$1$clock = clock;
        wx_q$1$d = wx;
        wy_last$1$clock = clock;
        wy_last$1$d = wy_q$2$q;
        ch$1$clock = clock;
        ch$1$c00 = c00$1;
        ch$1$c10 = c10$1;
        ch$1$c01 = c01$1;
        ch$1$c11 = c11$1;
        ch$1$wx = wx_q$1$q;
        ch$1$wy = wy_last$1$q;
        out$1 = ch$1$y;
        wx_q$2$clock = clock;
        wx_q$2$d = wx;
        wy_last$2$clock = clock;
        wy_last$2$d = wy_q$2$q;
        ch$2$clock = clock;
        ch$2$c00 = c00$2;
        ch$2$c10 = c10$2;
        ch$2$c01 = c01$2;
        ch$2$c11 = c11$2;
        ch$2$wx = wx_q$2$q;
        ch$2$wy = wy_last$2$q;
        out$2 = ch$2$y;
        wx_q$3$clock = clock;
        wx_q$3$d = wx;
        wy_last$3$clock = clock;
        wy_last$3$d = wy_q$2$q;
        ch$3$clock = clock;
        ch$3$c00 = c00$3;
        ch$3$c10 = c10$3;
        ch$3$c01 = c01$3;
        ch$3$c11 = c11$3;
        ch$3$wx = wx_q$3$q;
        ch$3$wy = wy_last$3$q;
        out$3 = ch$3$y;
    end
    
endmodule // top$lanes$1$bilinear
module top$lanes$1$bilinear$ch$0(clock,c00,c10,c01,c11,wx,wy,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] c00;
    input wire  [31:0] c10;
    input wire  [31:0] c01;
    input wire  [31:0] c11;
    input wire  [15:0] wx;
    input wire  [15:0] wy;
    output reg  [31:0] y;
    
    // Stub signals
    reg  top$clock;
    reg  [31:0] top$a;
    reg  [31:0] top$b;
    reg  [15:0] top$w;
    wire  [31:0] top$y;
    reg  bottom$clock;
    reg  [31:0] bottom$a;
    reg  [31:0] bottom$b;
    reg  [15:0] bottom$w;
    wire  [31:0] bottom$y;
    reg  vertical$clock;
    reg  [31:0] vertical$a;
    reg  [31:0] vertical$b;
    reg  [15:0] vertical$w;
    wire  [31:0] vertical$y;
    reg  [31:0] cells_q$0$d;
    wire  [31:0] cells_q$0$q;
    reg  cells_q$0$clock;
    reg  [31:0] cells_q$1$d;
    wire  [31:0] cells_q$1$q;
    reg  cells_q$1$clock;
    reg  [31:0] cells_q$2$d;
    wire  [31:0] cells_q$2$q;
    reg  cells_q$2$clock;
    reg  [31:0] cells_q$3$d;
    wire  [31:0] cells_q$3$q;
    reg  cells_q$3$clock;
    
    // Sub module instances
    top$lanes$1$bilinear$ch$0$top top(
        .clock(top$clock),
        .a(top$a),
        .b(top$b),
        .w(top$w),
        .y(top$y)
    );
    top$lanes$1$bilinear$ch$0$bottom bottom(
        .clock(bottom$clock),
        .a(bottom$a),
        .b(bottom$b),
        .w(bottom$w),
        .y(bottom$y)
    );
    top$lanes$1$bilinear$ch$0$vertical vertical(
        .clock(vertical$clock),
        .a(vertical$a),
        .b(vertical$b),
        .w(vertical$w),
        .y(vertical$y)
    );
    top$lanes$1$bilinear$ch$0$cells_q$0 cells_q$0(
        .d(cells_q$0$d),
        .q(cells_q$0$q),
        .clock(cells_q$0$clock)
    );
    top$lanes$1$bilinear$ch$0$cells_q$1 cells_q$1(
        .d(cells_q$1$d),
        .q(cells_q$1$q),
        .clock(cells_q$1$clock)
    );
    top$lanes$1$bilinear$ch$0$cells_q$2 cells_q$2(
        .d(cells_q$2$d),
        .q(cells_q$2$q),
        .clock(cells_q$2$clock)
    );
    top$lanes$1$bilinear$ch$0$cells_q$3 cells_q$3(
        .d(cells_q$3$d),
        .q(cells_q$3$q),
        .clock(cells_q$3$clock)
    );
    
    // Update code
    always @(*) begin
        cells_q$0$clock = clock;
        cells_q$1$clock = clock;
        cells_q$2$clock = clock;
        cells_q$3$clock = clock;
        top$clock = clock;
        bottom$clock = clock;
        vertical$clock = clock;
        cells_q$0$d = c00;
        cells_q$1$d = c10;
        cells_q$2$d = c01;
        cells_q$3$d = c11;
        top$a = cells_q$0$q;
        top$b = cells_q$1$q;
        top$w = wx;
        bottom$a = cells_q$2$q;
        bottom$b = cells_q$3$q;
        bottom$w = wx;
        vertical$a = top$y;
        vertical$b = bottom$y;
        vertical$w = wy;
        y = vertical$y;
    end
    
endmodule // top$lanes$1$bilinear$ch$0
module top$lanes$1$bilinear$ch$0$bottom(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$lanes$1$bilinear$ch$0$bottom$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$lanes$1$bilinear$ch$0$bottom$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$lanes$1$bilinear$ch$0$bottom$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$lanes$1$bilinear$ch$0$bottom$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$lanes$1$bilinear$ch$0$bottom$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$lanes$1$bilinear$ch$0$bottom$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$lanes$1$bilinear$ch$0$bottom$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$lanes$1$bilinear$ch$0$bottom$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$lanes$1$bilinear$ch$0$bottom$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$lanes$1$bilinear$ch$0$bottom
module top$lanes$1$bilinear$ch$0$bottom$a_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$0$bottom$a_q
module top$lanes$1$bilinear$ch$0$bottom$a_q2(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$0$bottom$a_q2
module top$lanes$1$bilinear$ch$0$bottom$diff_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$0$bottom$diff_q
module top$lanes$1$bilinear$ch$0$bottom$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$lanes$1$bilinear$ch$0$bottom$narrow
module top$lanes$1$bilinear$ch$0$bottom$prod_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$0$bottom$prod_q
module top$lanes$1$bilinear$ch$0$bottom$up_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$0$bottom$up_q
module top$lanes$1$bilinear$ch$0$bottom$up_q2(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$0$bottom$up_q2
module top$lanes$1$bilinear$ch$0$bottom$w_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$0$bottom$w_q
module top$lanes$1$bilinear$ch$0$bottom$y_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$0$bottom$y_q
module top$lanes$1$bilinear$ch$0$cells_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$0$cells_q$0
module top$lanes$1$bilinear$ch$0$cells_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$0$cells_q$1
module top$lanes$1$bilinear$ch$0$cells_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$0$cells_q$2
module top$lanes$1$bilinear$ch$0$cells_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$0$cells_q$3
module top$lanes$1$bilinear$ch$0$top(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$lanes$1$bilinear$ch$0$top$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$lanes$1$bilinear$ch$0$top$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$lanes$1$bilinear$ch$0$top$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$lanes$1$bilinear$ch$0$top$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$lanes$1$bilinear$ch$0$top$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$lanes$1$bilinear$ch$0$top$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$lanes$1$bilinear$ch$0$top$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$lanes$1$bilinear$ch$0$top$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$lanes$1$bilinear$ch$0$top$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$lanes$1$bilinear$ch$0$top
module top$lanes$1$bilinear$ch$0$top$a_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$0$top$a_q
module top$lanes$1$bilinear$ch$0$top$a_q2(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$0$top$a_q2
module top$lanes$1$bilinear$ch$0$top$diff_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$0$top$diff_q
module top$lanes$1$bilinear$ch$0$top$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$lanes$1$bilinear$ch$0$top$narrow
module top$lanes$1$bilinear$ch$0$top$prod_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$0$top$prod_q
module top$lanes$1$bilinear$ch$0$top$up_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$0$top$up_q
module top$lanes$1$bilinear$ch$0$top$up_q2(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$0$top$up_q2
module top$lanes$1$bilinear$ch$0$top$w_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$0$top$w_q
module top$lanes$1$bilinear$ch$0$top$y_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$0$top$y_q
module top$lanes$1$bilinear$ch$0$vertical(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$lanes$1$bilinear$ch$0$vertical$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$lanes$1$bilinear$ch$0$vertical$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$lanes$1$bilinear$ch$0$vertical$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$lanes$1$bilinear$ch$0$vertical$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$lanes$1$bilinear$ch$0$vertical$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$lanes$1$bilinear$ch$0$vertical$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$lanes$1$bilinear$ch$0$vertical$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$lanes$1$bilinear$ch$0$vertical$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$lanes$1$bilinear$ch$0$vertical$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$lanes$1$bilinear$ch$0$vertical
module top$lanes$1$bilinear$ch$0$vertical$a_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$0$vertical$a_q
module top$lanes$1$bilinear$ch$0$vertical$a_q2(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$0$vertical$a_q2
module top$lanes$1$bilinear$ch$0$vertical$diff_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$0$vertical$diff_q
module top$lanes$1$bilinear$ch$0$vertical$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$lanes$1$bilinear$ch$0$vertical$narrow
module top$lanes$1$bilinear$ch$0$vertical$prod_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$0$vertical$prod_q
module top$lanes$1$bilinear$ch$0$vertical$up_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$0$vertical$up_q
module top$lanes$1$bilinear$ch$0$vertical$up_q2(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$0$vertical$up_q2
module top$lanes$1$bilinear$ch$0$vertical$w_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$0$vertical$w_q
module top$lanes$1$bilinear$ch$0$vertical$y_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$0$vertical$y_q
module top$lanes$1$bilinear$ch$1(clock,c00,c10,c01,c11,wx,wy,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] c00;
    input wire  [31:0] c10;
    input wire  [31:0] c01;
    input wire  [31:0] c11;
    input wire  [15:0] wx;
    input wire  [15:0] wy;
    output reg  [31:0] y;
    
    // Stub signals
    reg  top$clock;
    reg  [31:0] top$a;
    reg  [31:0] top$b;
    reg  [15:0] top$w;
    wire  [31:0] top$y;
    reg  bottom$clock;
    reg  [31:0] bottom$a;
    reg  [31:0] bottom$b;
    reg  [15:0] bottom$w;
    wire  [31:0] bottom$y;
    reg  vertical$clock;
    reg  [31:0] vertical$a;
    reg  [31:0] vertical$b;
    reg  [15:0] vertical$w;
    wire  [31:0] vertical$y;
    reg  [31:0] cells_q$0$d;
    wire  [31:0] cells_q$0$q;
    reg  cells_q$0$clock;
    reg  [31:0] cells_q$1$d;
    wire  [31:0] cells_q$1$q;
    reg  cells_q$1$clock;
    reg  [31:0] cells_q$2$d;
    wire  [31:0] cells_q$2$q;
    reg  cells_q$2$clock;
    reg  [31:0] cells_q$3$d;
    wire  [31:0] cells_q$3$q;
    reg  cells_q$3$clock;
    
    // Sub module instances
    top$lanes$1$bilinear$ch$1$top top(
        .clock(top$clock),
        .a(top$a),
        .b(top$b),
        .w(top$w),
        .y(top$y)
    );
    top$lanes$1$bilinear$ch$1$bottom bottom(
        .clock(bottom$clock),
        .a(bottom$a),
        .b(bottom$b),
        .w(bottom$w),
        .y(bottom$y)
    );
    top$lanes$1$bilinear$ch$1$vertical vertical(
        .clock(vertical$clock),
        .a(vertical$a),
        .b(vertical$b),
        .w(vertical$w),
        .y(vertical$y)
    );
    top$lanes$1$bilinear$ch$1$cells_q$0 cells_q$0(
        .d(cells_q$0$d),
        .q(cells_q$0$q),
        .clock(cells_q$0$clock)
    );
    top$lanes$1$bilinear$ch$1$cells_q$1 cells_q$1(
        .d(cells_q$1$d),
        .q(cells_q$1$q),
        .clock(cells_q$1$clock)
    );
    top$lanes$1$bilinear$ch$1$cells_q$2 cells_q$2(
        .d(cells_q$2$d),
        .q(cells_q$2$q),
        .clock(cells_q$2$clock)
    );
    top$lanes$1$bilinear$ch$1$cells_q$3 cells_q$3(
        .d(cells_q$3$d),
        .q(cells_q$3$q),
        .clock(cells_q$3$clock)
    );
    
    // Update code
    always @(*) begin
        cells_q$0$clock = clock;
        cells_q$1$clock = clock;
        cells_q$2$clock = clock;
        cells_q$3$clock = clock;
        top$clock = clock;
        bottom$clock = clock;
        vertical$clock = clock;
        cells_q$0$d = c00;
        cells_q$1$d = c10;
        cells_q$2$d = c01;
        cells_q$3$d = c11;
        top$a = cells_q$0$q;
        top$b = cells_q$1$q;
        top$w = wx;
        bottom$a = cells_q$2$q;
        bottom$b = cells_q$3$q;
        bottom$w = wx;
        vertical$a = top$y;
        vertical$b = bottom$y;
        vertical$w = wy;
        y = vertical$y;
    end
    
endmodule // top$lanes$1$bilinear$ch$1
module top$lanes$1$bilinear$ch$1$bottom(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$lanes$1$bilinear$ch$1$bottom$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$lanes$1$bilinear$ch$1$bottom$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$lanes$1$bilinear$ch$1$bottom$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$lanes$1$bilinear$ch$1$bottom$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$lanes$1$bilinear$ch$1$bottom$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$lanes$1$bilinear$ch$1$bottom$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$lanes$1$bilinear$ch$1$bottom$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$lanes$1$bilinear$ch$1$bottom$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$lanes$1$bilinear$ch$1$bottom$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$lanes$1$bilinear$ch$1$bottom
module top$lanes$1$bilinear$ch$1$bottom$a_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$1$bottom$a_q
module top$lanes$1$bilinear$ch$1$bottom$a_q2(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$1$bottom$a_q2
module top$lanes$1$bilinear$ch$1$bottom$diff_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$1$bottom$diff_q
module top$lanes$1$bilinear$ch$1$bottom$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$lanes$1$bilinear$ch$1$bottom$narrow
module top$lanes$1$bilinear$ch$1$bottom$prod_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$1$bottom$prod_q
module top$lanes$1$bilinear$ch$1$bottom$up_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$1$bottom$up_q
module top$lanes$1$bilinear$ch$1$bottom$up_q2(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$1$bottom$up_q2
module top$lanes$1$bilinear$ch$1$bottom$w_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$1$bottom$w_q
module top$lanes$1$bilinear$ch$1$bottom$y_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$1$bottom$y_q
module top$lanes$1$bilinear$ch$1$cells_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$1$cells_q$0
module top$lanes$1$bilinear$ch$1$cells_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$1$cells_q$1
module top$lanes$1$bilinear$ch$1$cells_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$1$cells_q$2
module top$lanes$1$bilinear$ch$1$cells_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$1$cells_q$3
module top$lanes$1$bilinear$ch$1$top(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$lanes$1$bilinear$ch$1$top$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$lanes$1$bilinear$ch$1$top$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$lanes$1$bilinear$ch$1$top$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$lanes$1$bilinear$ch$1$top$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$lanes$1$bilinear$ch$1$top$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$lanes$1$bilinear$ch$1$top$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$lanes$1$bilinear$ch$1$top$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$lanes$1$bilinear$ch$1$top$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$lanes$1$bilinear$ch$1$top$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$lanes$1$bilinear$ch$1$top
module top$lanes$1$bilinear$ch$1$top$a_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$1$top$a_q
module top$lanes$1$bilinear$ch$1$top$a_q2(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$1$top$a_q2
module top$lanes$1$bilinear$ch$1$top$diff_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$1$top$diff_q
module top$lanes$1$bilinear$ch$1$top$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$lanes$1$bilinear$ch$1$top$narrow
module top$lanes$1$bilinear$ch$1$top$prod_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$1$top$prod_q
module top$lanes$1$bilinear$ch$1$top$up_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$1$top$up_q
module top$lanes$1$bilinear$ch$1$top$up_q2(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$1$top$up_q2
module top$lanes$1$bilinear$ch$1$top$w_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$1$top$w_q
module top$lanes$1$bilinear$ch$1$top$y_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$1$top$y_q
module top$lanes$1$bilinear$ch$1$vertical(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$lanes$1$bilinear$ch$1$vertical$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$lanes$1$bilinear$ch$1$vertical$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$lanes$1$bilinear$ch$1$vertical$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$lanes$1$bilinear$ch$1$vertical$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$lanes$1$bilinear$ch$1$vertical$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$lanes$1$bilinear$ch$1$vertical$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$lanes$1$bilinear$ch$1$vertical$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$lanes$1$bilinear$ch$1$vertical$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$lanes$1$bilinear$ch$1$vertical$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$lanes$1$bilinear$ch$1$vertical
module top$lanes$1$bilinear$ch$1$vertical$a_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$1$vertical$a_q
module top$lanes$1$bilinear$ch$1$vertical$a_q2(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$1$vertical$a_q2
module top$lanes$1$bilinear$ch$1$vertical$diff_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$1$vertical$diff_q
module top$lanes$1$bilinear$ch$1$vertical$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$lanes$1$bilinear$ch$1$vertical$narrow
module top$lanes$1$bilinear$ch$1$vertical$prod_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$1$vertical$prod_q
module top$lanes$1$bilinear$ch$1$vertical$up_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$1$vertical$up_q
module top$lanes$1$bilinear$ch$1$vertical$up_q2(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$1$vertical$up_q2
module top$lanes$1$bilinear$ch$1$vertical$w_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$1$vertical$w_q
module top$lanes$1$bilinear$ch$1$vertical$y_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$1$vertical$y_q
module top$lanes$1$bilinear$ch$2(clock,c00,c10,c01,c11,wx,wy,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] c00;
    input wire  [31:0] c10;
    input wire  [31:0] c01;
    input wire  [31:0] c11;
    input wire  [15:0] wx;
    input wire  [15:0] wy;
    output reg  [31:0] y;
    
    // Stub signals
    reg  top$clock;
    reg  [31:0] top$a;
    reg  [31:0] top$b;
    reg  [15:0] top$w;
    wire  [31:0] top$y;
    reg  bottom$clock;
    reg  [31:0] bottom$a;
    reg  [31:0] bottom$b;
    reg  [15:0] bottom$w;
    wire  [31:0] bottom$y;
    reg  vertical$clock;
    reg  [31:0] vertical$a;
    reg  [31:0] vertical$b;
    reg  [15:0] vertical$w;
    wire  [31:0] vertical$y;
    reg  [31:0] cells_q$0$d;
    wire  [31:0] cells_q$0$q;
    reg  cells_q$0$clock;
    reg  [31:0] cells_q$1$d;
    wire  [31:0] cells_q$1$q;
    reg  cells_q$1$clock;
    reg  [31:0] cells_q$2$d;
    wire  [31:0] cells_q$2$q;
    reg  cells_q$2$clock;
    reg  [31:0] cells_q$3$d;
    wire  [31:0] cells_q$3$q;
    reg  cells_q$3$clock;
    
    // Sub module instances
    top$lanes$1$bilinear$ch$2$top top(
        .clock(top$clock),
        .a(top$a),
        .b(top$b),
        .w(top$w),
        .y(top$y)
    );
    top$lanes$1$bilinear$ch$2$bottom bottom(
        .clock(bottom$clock),
        .a(bottom$a),
        .b(bottom$b),
        .w(bottom$w),
        .y(bottom$y)
    );
    top$lanes$1$bilinear$ch$2$vertical vertical(
        .clock(vertical$clock),
        .a(vertical$a),
        .b(vertical$b),
        .w(vertical$w),
        .y(vertical$y)
    );
    top$lanes$1$bilinear$ch$2$cells_q$0 cells_q$0(
        .d(cells_q$0$d),
        .q(cells_q$0$q),
        .clock(cells_q$0$clock)
    );
    top$lanes$1$bilinear$ch$2$cells_q$1 cells_q$1(
        .d(cells_q$1$d),
        .q(cells_q$1$q),
        .clock(cells_q$1$clock)
    );
    top$lanes$1$bilinear$ch$2$cells_q$2 cells_q$2(
        .d(cells_q$2$d),
        .q(cells_q$2$q),
        .clock(cells_q$2$clock)
    );
    top$lanes$1$bilinear$ch$2$cells_q$3 cells_q$3(
        .d(cells_q$3$d),
        .q(cells_q$3$q),
        .clock(cells_q$3$clock)
    );
    
    // Update code
    always @(*) begin
        cells_q$0$clock = clock;
        cells_q$1$clock = clock;
        cells_q$2$clock = clock;
        cells_q$3$clock = clock;
        top$clock = clock;
        bottom$clock = clock;
        vertical$clock = clock;
        cells_q$0$d = c00;
        cells_q$1$d = c10;
        cells_q$2$d = c01;
        cells_q$3$d = c11;
        top$a = cells_q$0$q;
        top$b = cells_q$1$q;
        top$w = wx;
        bottom$a = cells_q$2$q;
        bottom$b = cells_q$3$q;
        bottom$w = wx;
        vertical$a = top$y;
        vertical$b = bottom$y;
        vertical$w = wy;
        y = vertical$y;
    end
    
endmodule // top$lanes$1$bilinear$ch$2
module top$lanes$1$bilinear$ch$2$bottom(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$lanes$1$bilinear$ch$2$bottom$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$lanes$1$bilinear$ch$2$bottom$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$lanes$1$bilinear$ch$2$bottom$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$lanes$1$bilinear$ch$2$bottom$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$lanes$1$bilinear$ch$2$bottom$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$lanes$1$bilinear$ch$2$bottom$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$lanes$1$bilinear$ch$2$bottom$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$lanes$1$bilinear$ch$2$bottom$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$lanes$1$bilinear$ch$2$bottom$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$lanes$1$bilinear$ch$2$bottom
module top$lanes$1$bilinear$ch$2$bottom$a_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$2$bottom$a_q
module top$lanes$1$bilinear$ch$2$bottom$a_q2(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$2$bottom$a_q2
module top$lanes$1$bilinear$ch$2$bottom$diff_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$2$bottom$diff_q
module top$lanes$1$bilinear$ch$2$bottom$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$lanes$1$bilinear$ch$2$bottom$narrow
module top$lanes$1$bilinear$ch$2$bottom$prod_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$2$bottom$prod_q
module top$lanes$1$bilinear$ch$2$bottom$up_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$2$bottom$up_q
module top$lanes$1$bilinear$ch$2$bottom$up_q2(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$2$bottom$up_q2
module top$lanes$1$bilinear$ch$2$bottom$w_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$2$bottom$w_q
module top$lanes$1$bilinear$ch$2$bottom$y_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$2$bottom$y_q
module top$lanes$1$bilinear$ch$2$cells_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$2$cells_q$0
module top$lanes$1$bilinear$ch$2$cells_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$2$cells_q$1
module top$lanes$1$bilinear$ch$2$cells_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$2$cells_q$2
module top$lanes$1$bilinear$ch$2$cells_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$2$cells_q$3
module top$lanes$1$bilinear$ch$2$top(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$lanes$1$bilinear$ch$2$top$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$lanes$1$bilinear$ch$2$top$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$lanes$1$bilinear$ch$2$top$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$lanes$1$bilinear$ch$2$top$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$lanes$1$bilinear$ch$2$top$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$lanes$1$bilinear$ch$2$top$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$lanes$1$bilinear$ch$2$top$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$lanes$1$bilinear$ch$2$top$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$lanes$1$bilinear$ch$2$top$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$lanes$1$bilinear$ch$2$top
module top$lanes$1$bilinear$ch$2$top$a_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$2$top$a_q
module top$lanes$1$bilinear$ch$2$top$a_q2(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$2$top$a_q2
module top$lanes$1$bilinear$ch$2$top$diff_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$2$top$diff_q
module top$lanes$1$bilinear$ch$2$top$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$lanes$1$bilinear$ch$2$top$narrow
module top$lanes$1$bilinear$ch$2$top$prod_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$2$top$prod_q
module top$lanes$1$bilinear$ch$2$top$up_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$2$top$up_q
module top$lanes$1$bilinear$ch$2$top$up_q2(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$2$top$up_q2
module top$lanes$1$bilinear$ch$2$top$w_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$2$top$w_q
module top$lanes$1$bilinear$ch$2$top$y_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$2$top$y_q
module top$lanes$1$bilinear$ch$2$vertical(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$lanes$1$bilinear$ch$2$vertical$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$lanes$1$bilinear$ch$2$vertical$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$lanes$1$bilinear$ch$2$vertical$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$lanes$1$bilinear$ch$2$vertical$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$lanes$1$bilinear$ch$2$vertical$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$lanes$1$bilinear$ch$2$vertical$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$lanes$1$bilinear$ch$2$vertical$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$lanes$1$bilinear$ch$2$vertical$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$lanes$1$bilinear$ch$2$vertical$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$lanes$1$bilinear$ch$2$vertical
module top$lanes$1$bilinear$ch$2$vertical$a_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$2$vertical$a_q
module top$lanes$1$bilinear$ch$2$vertical$a_q2(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$2$vertical$a_q2
module top$lanes$1$bilinear$ch$2$vertical$diff_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$2$vertical$diff_q
module top$lanes$1$bilinear$ch$2$vertical$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$lanes$1$bilinear$ch$2$vertical$narrow
module top$lanes$1$bilinear$ch$2$vertical$prod_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$2$vertical$prod_q
module top$lanes$1$bilinear$ch$2$vertical$up_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$2$vertical$up_q
module top$lanes$1$bilinear$ch$2$vertical$up_q2(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$2$vertical$up_q2
module top$lanes$1$bilinear$ch$2$vertical$w_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$2$vertical$w_q
module top$lanes$1$bilinear$ch$2$vertical$y_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$2$vertical$y_q
module top$lanes$1$bilinear$ch$3(clock,c00,c10,c01,c11,wx,wy,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] c00;
    input wire  [31:0] c10;
    input wire  [31:0] c01;
    input wire  [31:0] c11;
    input wire  [15:0] wx;
    input wire  [15:0] wy;
    output reg  [31:0] y;
    
    // Stub signals
    reg  top$clock;
    reg  [31:0] top$a;
    reg  [31:0] top$b;
    reg  [15:0] top$w;
    wire  [31:0] top$y;
    reg  bottom$clock;
    reg  [31:0] bottom$a;
    reg  [31:0] bottom$b;
    reg  [15:0] bottom$w;
    wire  [31:0] bottom$y;
    reg  vertical$clock;
    reg  [31:0] vertical$a;
    reg  [31:0] vertical$b;
    reg  [15:0] vertical$w;
    wire  [31:0] vertical$y;
    reg  [31:0] cells_q$0$d;
    wire  [31:0] cells_q$0$q;
    reg  cells_q$0$clock;
    reg  [31:0] cells_q$1$d;
    wire  [31:0] cells_q$1$q;
    reg  cells_q$1$clock;
    reg  [31:0] cells_q$2$d;
    wire  [31:0] cells_q$2$q;
    reg  cells_q$2$clock;
    reg  [31:0] cells_q$3$d;
    wire  [31:0] cells_q$3$q;
    reg  cells_q$3$clock;
    
    // Sub module instances
    top$lanes$1$bilinear$ch$3$top top(
        .clock(top$clock),
        .a(top$a),
        .b(top$b),
        .w(top$w),
        .y(top$y)
    );
    top$lanes$1$bilinear$ch$3$bottom bottom(
        .clock(bottom$clock),
        .a(bottom$a),
        .b(bottom$b),
        .w(bottom$w),
        .y(bottom$y)
    );
    top$lanes$1$bilinear$ch$3$vertical vertical(
        .clock(vertical$clock),
        .a(vertical$a),
        .b(vertical$b),
        .w(vertical$w),
        .y(vertical$y)
    );
    top$lanes$1$bilinear$ch$3$cells_q$0 cells_q$0(
        .d(cells_q$0$d),
        .q(cells_q$0$q),
        .clock(cells_q$0$clock)
    );
    top$lanes$1$bilinear$ch$3$cells_q$1 cells_q$1(
        .d(cells_q$1$d),
        .q(cells_q$1$q),
        .clock(cells_q$1$clock)
    );
    top$lanes$1$bilinear$ch$3$cells_q$2 cells_q$2(
        .d(cells_q$2$d),
        .q(cells_q$2$q),
        .clock(cells_q$2$clock)
    );
    top$lanes$1$bilinear$ch$3$cells_q$3 cells_q$3(
        .d(cells_q$3$d),
        .q(cells_q$3$q),
        .clock(cells_q$3$clock)
    );
    
    // Update code
    always @(*) begin
        cells_q$0$clock = clock;
        cells_q$1$clock = clock;
        cells_q$2$clock = clock;
        cells_q$3$clock = clock;
        top$clock = clock;
        bottom$clock = clock;
        vertical$clock = clock;
        cells_q$0$d = c00;
        cells_q$1$d = c10;
        cells_q$2$d = c01;
        cells_q$3$d = c11;
        top$a = cells_q$0$q;
        top$b = cells_q$1$q;
        top$w = wx;
        bottom$a = cells_q$2$q;
        bottom$b = cells_q$3$q;
        bottom$w = wx;
        vertical$a = top$y;
        vertical$b = bottom$y;
        vertical$w = wy;
        y = vertical$y;
    end
    
endmodule // top$lanes$1$bilinear$ch$3
module top$lanes$1$bilinear$ch$3$bottom(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$lanes$1$bilinear$ch$3$bottom$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$lanes$1$bilinear$ch$3$bottom$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$lanes$1$bilinear$ch$3$bottom$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$lanes$1$bilinear$ch$3$bottom$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$lanes$1$bilinear$ch$3$bottom$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$lanes$1$bilinear$ch$3$bottom$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$lanes$1$bilinear$ch$3$bottom$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$lanes$1$bilinear$ch$3$bottom$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$lanes$1$bilinear$ch$3$bottom$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$lanes$1$bilinear$ch$3$bottom
module top$lanes$1$bilinear$ch$3$bottom$a_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$3$bottom$a_q
module top$lanes$1$bilinear$ch$3$bottom$a_q2(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$3$bottom$a_q2
module top$lanes$1$bilinear$ch$3$bottom$diff_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$3$bottom$diff_q
module top$lanes$1$bilinear$ch$3$bottom$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$lanes$1$bilinear$ch$3$bottom$narrow
module top$lanes$1$bilinear$ch$3$bottom$prod_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$3$bottom$prod_q
module top$lanes$1$bilinear$ch$3$bottom$up_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$3$bottom$up_q
module top$lanes$1$bilinear$ch$3$bottom$up_q2(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$3$bottom$up_q2
module top$lanes$1$bilinear$ch$3$bottom$w_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$3$bottom$w_q
module top$lanes$1$bilinear$ch$3$bottom$y_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$3$bottom$y_q
module top$lanes$1$bilinear$ch$3$cells_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$3$cells_q$0
module top$lanes$1$bilinear$ch$3$cells_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$3$cells_q$1
module top$lanes$1$bilinear$ch$3$cells_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$3$cells_q$2
module top$lanes$1$bilinear$ch$3$cells_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$3$cells_q$3
module top$lanes$1$bilinear$ch$3$top(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$lanes$1$bilinear$ch$3$top$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$lanes$1$bilinear$ch$3$top$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$lanes$1$bilinear$ch$3$top$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$lanes$1$bilinear$ch$3$top$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$lanes$1$bilinear$ch$3$top$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$lanes$1$bilinear$ch$3$top$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$lanes$1$bilinear$ch$3$top$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$lanes$1$bilinear$ch$3$top$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$lanes$1$bilinear$ch$3$top$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$lanes$1$bilinear$ch$3$top
module top$lanes$1$bilinear$ch$3$top$a_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$3$top$a_q
module top$lanes$1$bilinear$ch$3$top$a_q2(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$3$top$a_q2
module top$lanes$1$bilinear$ch$3$top$diff_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$3$top$diff_q
module top$lanes$1$bilinear$ch$3$top$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$lanes$1$bilinear$ch$3$top$narrow
module top$lanes$1$bilinear$ch$3$top$prod_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$3$top$prod_q
module top$lanes$1$bilinear$ch$3$top$up_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$3$top$up_q
module top$lanes$1$bilinear$ch$3$top$up_q2(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$3$top$up_q2
module top$lanes$1$bilinear$ch$3$top$w_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$3$top$w_q
module top$lanes$1$bilinear$ch$3$top$y_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$3$top$y_q
module top$lanes$1$bilinear$ch$3$vertical(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$lanes$1$bilinear$ch$3$vertical$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$lanes$1$bilinear$ch$3$vertical$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$lanes$1$bilinear$ch$3$vertical$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$lanes$1$bilinear$ch$3$vertical$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$lanes$1$bilinear$ch$3$vertical$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$lanes$1$bilinear$ch$3$vertical$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$lanes$1$bilinear$ch$3$vertical$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$lanes$1$bilinear$ch$3$vertical$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$lanes$1$bilinear$ch$3$vertical$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$lanes$1$bilinear$ch$3$vertical
module top$lanes$1$bilinear$ch$3$vertical$a_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$3$vertical$a_q
module top$lanes$1$bilinear$ch$3$vertical$a_q2(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$3$vertical$a_q2
module top$lanes$1$bilinear$ch$3$vertical$diff_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$3$vertical$diff_q
module top$lanes$1$bilinear$ch$3$vertical$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$lanes$1$bilinear$ch$3$vertical$narrow
module top$lanes$1$bilinear$ch$3$vertical$prod_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$3$vertical$prod_q
module top$lanes$1$bilinear$ch$3$vertical$up_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$3$vertical$up_q
module top$lanes$1$bilinear$ch$3$vertical$up_q2(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$3$vertical$up_q2
module top$lanes$1$bilinear$ch$3$vertical$w_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$3$vertical$w_q
module top$lanes$1$bilinear$ch$3$vertical$y_q(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$ch$3$vertical$y_q
module top$lanes$1$bilinear$wx_q$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$1$bilinear$wx_q$0
module top$lanes$1$bilinear$wx_q$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$1$bilinear$wx_q$1
module top$lanes$1$bilinear$wx_q$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$1$bilinear$wx_q$2
module top$lanes$1$bilinear$wx_q$3(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$1$bilinear$wx_q$3
module top$lanes$1$bilinear$wy_last$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$1$bilinear$wy_last$0
module top$lanes$1$bilinear$wy_last$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$1$bilinear$wy_last$1
module top$lanes$1$bilinear$wy_last$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$1$bilinear$wy_last$2
module top$lanes$1$bilinear$wy_last$3(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$1$bilinear$wy_last$3
module top$lanes$1$bilinear$wy_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$wy_q$0
module top$lanes$1$bilinear$wy_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$wy_q$1
module top$lanes$1$bilinear$wy_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$1$bilinear$wy_q$2
module top$lanes$2$bilinear(clock,c00$0,c00$1,c00$2,c00$3,c10$0,c10$1,c10$2,c10$3,c01$0,c01$1,c01$2,c01$3,c11$0,c11$1,c11$2,c11$3,wx,wy,out$0,out$1,out$2,out$3);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] c00$0;
    input wire  [31:0] c00$1;
    input wire  [31:0] c00$2;
    input wire  [31:0] c00$3;
    input wire  [31:0] c10$0;
    input wire  [31:0] c10$1;
    input wire  [31:0] c10$2;
    input wire  [31:0] c10$3;
    input wire  [31:0] c01$0;
    input wire  [31:0] c01$1;
    input wire  [31:0] c01$2;
    input wire  [31:0] c01$3;
    input wire  [31:0] c11$0;
    input wire  [31:0] c11$1;
    input wire  [31:0] c11$2;
    input wire  [31:0] c11$3;
    input wire  [15:0] wx;
    input wire  [15:0] wy;
    output reg  [31:0] out$0;
    output reg  [31:0] out$1;
    output reg  [31:0] out$2;
    output reg  [31:0] out$3;
    
    // Stub signals
    reg  [15:0] wx_q$0$d;
    wire  [15:0] wx_q$0$q;
    reg  wx_q$0$clock;
    reg  [15:0] wx_q$1$d;
    wire  [15:0] wx_q$1$q;
    reg  wx_q$1$clock;
    reg  [15:0] wx_q$2$d;
    wire  [15:0] wx_q$2$q;
    reg  wx_q$2$clock;
    reg  [15:0] wx_q$3$d;
    wire  [15:0] wx_q$3$q;
    reg  wx_q$3$clock;
    reg  [15:0] wy_q$0$d;
    wire  [15:0] wy_q$0$q;
    reg  wy_q$0$clock;
    reg  [15:0] wy_q$1$d;
    wire  [15:0] wy_q$1$q;
    reg  wy_q$1$clock;
    reg  [15:0] wy_q$2$d;
    wire  [15:0] wy_q$2$q;
    reg  wy_q$2$clock;
    reg  [15:0] wy_last$0$d;
    wire  [15:0] wy_last$0$q;
    reg  wy_last$0$clock;
    reg  [15:0] wy_last$1$d;
    wire  [15:0] wy_last$1$q;
    reg  wy_last$1$clock;
    reg  [15:0] wy_last$2$d;
    wire  [15:0] wy_last$2$q;
    reg  wy_last$2$clock;
    reg  [15:0] wy_last$3$d;
    wire  [15:0] wy_last$3$q;
    reg  wy_last$3$clock;
    reg  ch$0$clock;
    reg  [31:0] ch$0$c00;
    reg  [31:0] ch$0$c10;
    reg  [31:0] ch$0$c01;
    reg  [31:0] ch$0$c11;
    reg  [15:0] ch$0$wx;
    reg  [15:0] ch$0$wy;
    wire  [31:0] ch$0$y;
    reg  ch$1$clock;
    reg  [31:0] ch$1$c00;
    reg  [31:0] ch$1$c10;
    reg  [31:0] ch$1$c01;
    reg  [31:0] ch$1$c11;
    reg  [15:0] ch$1$wx;
    reg  [15:0] ch$1$wy;
    wire  [31:0] ch$1$y;
    reg  ch$2$clock;
    reg  [31:0] ch$2$c00;
    reg  [31:0] ch$2$c10;
    reg  [31:0] ch$2$c01;
    reg  [31:0] ch$2$c11;
    reg  [15:0] ch$2$wx;
    reg  [15:0] ch$2$wy;
    wire  [31:0] ch$2$y;
    reg  ch$3$clock;
    reg  [31:0] ch$3$c00;
    reg  [31:0] ch$3$c10;
    reg  [31:0] ch$3$c01;
    reg  [31:0] ch$3$c11;
    reg  [15:0] ch$3$wx;
    reg  [15:0] ch$3$wy;
    wire  [31:0] ch$3$y;
    
    // Sub module instances
    top$lanes$2$bilinear$wx_q$0 wx_q$0(
        .d(wx_q$0$d),
        .q(wx_q$0$q),
        .clock(wx_q$0$clock)
    );
    top$lanes$2$bilinear$wx_q$1 wx_q$1(
        .d(wx_q$1$d),
        .q(wx_q$1$q),
        .clock(wx_q$1$clock)
    );
    top$lanes$2$bilinear$wx_q$2 wx_q$2(
        .d(wx_q$2$d),
        .q(wx_q$2$q),
        .clock(wx_q$2$clock)
    );
    top$lanes$2$bilinear$wx_q$3 wx_q$3(
        .d(wx_q$3$d),
        .q(wx_q$3$q),
        .clock(wx_q$3$clock)
    );
    top$lanes$2$bilinear$wy_q$0 wy_q$0(
        .d(wy_q$0$d),
        .q(wy_q$0$q),
        .clock(wy_q$0$clock)
    );
    top$lanes$2$bilinear$wy_q$1 wy_q$1(
        .d(wy_q$1$d),
        .q(wy_q$1$q),
        .clock(wy_q$1$clock)
    );
    top$lanes$2$bilinear$wy_q$2 wy_q$2(
        .d(wy_q$2$d),
        .q(wy_q$2$q),
        .clock(wy_q$2$clock)
    );
    top$lanes$2$bilinear$wy_last$0 wy_last$0(
        .d(wy_last$0$d),
        .q(wy_last$0$q),
        .clock(wy_last$0$clock)
    );
    top$lanes$2$bilinear$wy_last$1 wy_last$1(
        .d(wy_last$1$d),
        .q(wy_last$1$q),
        .clock(wy_last$1$clock)
    );
    top$lanes$2$bilinear$wy_last$2 wy_last$2(
        .d(wy_last$2$d),
        .q(wy_last$2$q),
        .clock(wy_last$2$clock)
    );
    top$lanes$2$bilinear$wy_last$3 wy_last$3(
        .d(wy_last$3$d),
        .q(wy_last$3$q),
        .clock(wy_last$3$clock)
    );
    top$lanes$2$bilinear$ch$0 ch$0(
        .clock(ch$0$clock),
        .c00(ch$0$c00),
        .c10(ch$0$c10),
        .c01(ch$0$c01),
        .c11(ch$0$c11),
        .wx(ch$0$wx),
        .wy(ch$0$wy),
        .y(ch$0$y)
    );
    top$lanes$2$bilinear$ch$1 ch$1(
        .clock(ch$1$clock),
        .c00(ch$1$c00),
        .c10(ch$1$c10),
        .c01(ch$1$c01),
        .c11(ch$1$c11),
        .wx(ch$1$wx),
        .wy(ch$1$wy),
        .y(ch$1$y)
    );
    top$lanes$2$bilinear$ch$2 ch$2(
        .clock(ch$2$clock),
        .c00(ch$2$c00),
        .c10(ch$2$c10),
        .c01(ch$2$c01),
        .c11(ch$2$c11),
        .wx(ch$2$wx),
        .wy(ch$2$wy),
        .y(ch$2$y)
    );
    top$lanes$2$bilinear$ch$3 ch$3(
        .clock(ch$3$clock),
        .c00(ch$3$c00),
        .c10(ch$3$c10),
        .c01(ch$3$c01),
        .c11(ch$3$c11),
        .wx(ch$3$wx),
        .wy(ch$3$wy),
        .y(ch$3$y)
    );
    
    // Update code
    always @(*) begin
        wy_q$0$clock = clock;
        wy_q$1$clock = clock;
        wy_q$2$clock = clock;
        wy_q$0$d = wy;
        wy_q$1$d = wy_q$0$q;
        wy_q$2$d = wy_q$1$q;
        wx_q$0$clock = clock;
        wx_q$0$d = wx;
        wy_last$0$clock = clock;
        wy_last$0$d = wy_q$2$q;
        ch$0$clock = clock;
        ch$0$c00 = c00$0;
        ch$0$c10 = c10$0;
        ch$0$c01 = c01$0;
        ch$0$c11 = c11$0;
        ch$0$wx = wx_q$0$q;
        ch$0$wy = wy_last$0$q;
        out$0 = ch$0$y;
        wx_q$1$clock = clock;
        wx_q$1$d = wx;
        wy_last$1$clock = clock;
        wy_last$1$d = wy_q$2$q;
        ch$1$clock = clock;
        ch$1$c00 = c00$1;
        ch$1$c10 = c10$1;
        ch$1$c01 = c01$1;
        ch$1$c11 = c11$1;
        ch$1$wx = wx_q$1$q;
        ch$1$wy = wy_last$1$q;
        out$1 = ch$1$y;
        wx_q$2$clock = clock;
        wx_q$2$d = wx;
        wy_last$2$clock = clock;
        wy_last$2$d = wy_q$2$q;
        ch$2$clock = clock;
        ch$2$c00 = c00$2;
        ch$2$c10 = c10$2;
        ch$2$c01 = c01$2;
        ch$2$c11 = c11$2;
        ch$2$wx = wx_q$2$q;
        ch$2$wy = wy_last$2$q;
        out$2 = ch$2$y;
        wx_q$3$clock = clock;
        wx_q$3$d = wx;
        wy_last$3$clock = clock;
        wy_last$3$d = wy_q$2$q;
        ch$3$clock = clock;
        ch$3$c00 = c00$3;
        ch$3$c10 = c10$3;
        ch$3$c01 = c01$3;
        ch$3$c11 = c11$3;
        ch$3$wx = wx_q$3$q;
        ch$3$wy = wy_last$3$q;
        out$3 = ch$3$y;
    end
    
endmodule // top$lanes$2$bilinear
module top$lanes$2$bilinear$ch$0(clock,c00,c10,c01,c11,wx,wy,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] c00;
    input wire  [31:0] c10;
    input wire  [31:0] c01;
    input wire  [31:0] c11;
    input wire  [15:0] wx;
    input wire  [15:0] wy;
    output reg  [31:0] y;
    
    // Stub signals
    reg  top$clock;
    reg  [31:0] top$a;
    reg  [31:0] top$b;
    reg  [15:0] top$w;
    wire  [31:0] top$y;
    reg  bottom$clock;
    reg  [31:0] bottom$a;
    reg  [31:0] bottom$b;
    reg  [15:0] bottom$w;
    wire  [31:0] bottom$y;
    reg  vertical$clock;
    reg  [31:0] vertical$a;
    reg  [31:0] vertical$b;
    reg  [15:0] vertical$w;
    wire  [31:0] vertical$y;
    reg  [31:0] cells_q$0$d;
    wire  [31:0] cells_q$0$q;
    reg  cells_q$0$clock;
    reg  [31:0] cells_q$1$d;
    wire  [31:0] cells_q$1$q;
    reg  cells_q$1$clock;
    reg  [31:0] cells_q$2$d;
    wire  [31:0] cells_q$2$q;
    reg  cells_q$2$clock;
    reg  [31:0] cells_q$3$d;
    wire  [31:0] cells_q$3$q;
    reg  cells_q$3$clock;
    
    // Sub module instances
    top$lanes$2$bilinear$ch$0$top top(
        .clock(top$clock),
        .a(top$a),
        .b(top$b),
        .w(top$w),
        .y(top$y)
    );
    top$lanes$2$bilinear$ch$0$bottom bottom(
        .clock(bottom$clock),
        .a(bottom$a),
        .b(bottom$b),
        .w(bottom$w),
        .y(bottom$y)
    );
    top$lanes$2$bilinear$ch$0$vertical vertical(
        .clock(vertical$clock),
        .a(vertical$a),
        .b(vertical$b),
        .w(vertical$w),
        .y(vertical$y)
    );
    top$lanes$2$bilinear$ch$0$cells_q$0 cells_q$0(
        .d(cells_q$0$d),
        .q(cells_q$0$q),
        .clock(cells_q$0$clock)
    );
    top$lanes$2$bilinear$ch$0$cells_q$1 cells_q$1(
        .d(cells_q$1$d),
        .q(cells_q$1$q),
        .clock(cells_q$1$clock)
    );
    top$lanes$2$bilinear$ch$0$cells_q$2 cells_q$2(
        .d(cells_q$2$d),
        .q(cells_q$2$q),
        .clock(cells_q$2$clock)
    );
    top$lanes$2$bilinear$ch$0$cells_q$3 cells_q$3(
        .d(cells_q$3$d),
        .q(cells_q$3$q),
        .clock(cells_q$3$clock)
    );
    
    // Update code
    always @(*) begin
        cells_q$0$clock = clock;
        cells_q$1$clock = clock;
        cells_q$2$clock = clock;
        cells_q$3$clock = clock;
        top$clock = clock;
        bottom$clock = clock;
        vertical$clock = clock;
        cells_q$0$d = c00;
        cells_q$1$d = c10;
        cells_q$2$d = c01;
        cells_q$3$d = c11;
        top$a = cells_q$0$q;
        top$b = cells_q$1$q;
        top$w = wx;
        bottom$a = cells_q$2$q;
        bottom$b = cells_q$3$q;
        bottom$w = wx;
        vertical$a = top$y;
        vertical$b = bottom$y;
        vertical$w = wy;
        y = vertical$y;
    end
    
endmodule // top$lanes$2$bilinear$ch$0
module top$lanes$2$bilinear$ch$0$bottom(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$lanes$2$bilinear$ch$0$bottom$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$lanes$2$bilinear$ch$0$bottom$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$lanes$2$bilinear$ch$0$bottom$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$lanes$2$bilinear$ch$0$bottom$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$lanes$2$bilinear$ch$0$bottom$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$lanes$2$bilinear$ch$0$bottom$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$lanes$2$bilinear$ch$0$bottom$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$lanes$2$bilinear$ch$0$bottom$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$lanes$2$bilinear$ch$0$bottom$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$lanes$2$bilinear$ch$0$bottom
module top$lanes$2$bilinear$ch$0$bottom$a_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$0$bottom$a_q
module top$lanes$2$bilinear$ch$0$bottom$a_q2(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$0$bottom$a_q2
module top$lanes$2$bilinear$ch$0$bottom$diff_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$0$bottom$diff_q
module top$lanes$2$bilinear$ch$0$bottom$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$lanes$2$bilinear$ch$0$bottom$narrow
module top$lanes$2$bilinear$ch$0$bottom$prod_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$0$bottom$prod_q
module top$lanes$2$bilinear$ch$0$bottom$up_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$0$bottom$up_q
module top$lanes$2$bilinear$ch$0$bottom$up_q2(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$0$bottom$up_q2
module top$lanes$2$bilinear$ch$0$bottom$w_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$0$bottom$w_q
module top$lanes$2$bilinear$ch$0$bottom$y_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$0$bottom$y_q
module top$lanes$2$bilinear$ch$0$cells_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$0$cells_q$0
module top$lanes$2$bilinear$ch$0$cells_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$0$cells_q$1
module top$lanes$2$bilinear$ch$0$cells_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$0$cells_q$2
module top$lanes$2$bilinear$ch$0$cells_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$0$cells_q$3
module top$lanes$2$bilinear$ch$0$top(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$lanes$2$bilinear$ch$0$top$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$lanes$2$bilinear$ch$0$top$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$lanes$2$bilinear$ch$0$top$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$lanes$2$bilinear$ch$0$top$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$lanes$2$bilinear$ch$0$top$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$lanes$2$bilinear$ch$0$top$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$lanes$2$bilinear$ch$0$top$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$lanes$2$bilinear$ch$0$top$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$lanes$2$bilinear$ch$0$top$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$lanes$2$bilinear$ch$0$top
module top$lanes$2$bilinear$ch$0$top$a_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$0$top$a_q
module top$lanes$2$bilinear$ch$0$top$a_q2(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$0$top$a_q2
module top$lanes$2$bilinear$ch$0$top$diff_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$0$top$diff_q
module top$lanes$2$bilinear$ch$0$top$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$lanes$2$bilinear$ch$0$top$narrow
module top$lanes$2$bilinear$ch$0$top$prod_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$0$top$prod_q
module top$lanes$2$bilinear$ch$0$top$up_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$0$top$up_q
module top$lanes$2$bilinear$ch$0$top$up_q2(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$0$top$up_q2
module top$lanes$2$bilinear$ch$0$top$w_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$0$top$w_q
module top$lanes$2$bilinear$ch$0$top$y_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$0$top$y_q
module top$lanes$2$bilinear$ch$0$vertical(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$lanes$2$bilinear$ch$0$vertical$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$lanes$2$bilinear$ch$0$vertical$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$lanes$2$bilinear$ch$0$vertical$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$lanes$2$bilinear$ch$0$vertical$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$lanes$2$bilinear$ch$0$vertical$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$lanes$2$bilinear$ch$0$vertical$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$lanes$2$bilinear$ch$0$vertical$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$lanes$2$bilinear$ch$0$vertical$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$lanes$2$bilinear$ch$0$vertical$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$lanes$2$bilinear$ch$0$vertical
module top$lanes$2$bilinear$ch$0$vertical$a_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$0$vertical$a_q
module top$lanes$2$bilinear$ch$0$vertical$a_q2(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$0$vertical$a_q2
module top$lanes$2$bilinear$ch$0$vertical$diff_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$0$vertical$diff_q
module top$lanes$2$bilinear$ch$0$vertical$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$lanes$2$bilinear$ch$0$vertical$narrow
module top$lanes$2$bilinear$ch$0$vertical$prod_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$0$vertical$prod_q
module top$lanes$2$bilinear$ch$0$vertical$up_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$0$vertical$up_q
module top$lanes$2$bilinear$ch$0$vertical$up_q2(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$0$vertical$up_q2
module top$lanes$2$bilinear$ch$0$vertical$w_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$0$vertical$w_q
module top$lanes$2$bilinear$ch$0$vertical$y_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$0$vertical$y_q
module top$lanes$2$bilinear$ch$1(clock,c00,c10,c01,c11,wx,wy,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] c00;
    input wire  [31:0] c10;
    input wire  [31:0] c01;
    input wire  [31:0] c11;
    input wire  [15:0] wx;
    input wire  [15:0] wy;
    output reg  [31:0] y;
    
    // Stub signals
    reg  top$clock;
    reg  [31:0] top$a;
    reg  [31:0] top$b;
    reg  [15:0] top$w;
    wire  [31:0] top$y;
    reg  bottom$clock;
    reg  [31:0] bottom$a;
    reg  [31:0] bottom$b;
    reg  [15:0] bottom$w;
    wire  [31:0] bottom$y;
    reg  vertical$clock;
    reg  [31:0] vertical$a;
    reg  [31:0] vertical$b;
    reg  [15:0] vertical$w;
    wire  [31:0] vertical$y;
    reg  [31:0] cells_q$0$d;
    wire  [31:0] cells_q$0$q;
    reg  cells_q$0$clock;
    reg  [31:0] cells_q$1$d;
    wire  [31:0] cells_q$1$q;
    reg  cells_q$1$clock;
    reg  [31:0] cells_q$2$d;
    wire  [31:0] cells_q$2$q;
    reg  cells_q$2$clock;
    reg  [31:0] cells_q$3$d;
    wire  [31:0] cells_q$3$q;
    reg  cells_q$3$clock;
    
    // Sub module instances
    top$lanes$2$bilinear$ch$1$top top(
        .clock(top$clock),
        .a(top$a),
        .b(top$b),
        .w(top$w),
        .y(top$y)
    );
    top$lanes$2$bilinear$ch$1$bottom bottom(
        .clock(bottom$clock),
        .a(bottom$a),
        .b(bottom$b),
        .w(bottom$w),
        .y(bottom$y)
    );
    top$lanes$2$bilinear$ch$1$vertical vertical(
        .clock(vertical$clock),
        .a(vertical$a),
        .b(vertical$b),
        .w(vertical$w),
        .y(vertical$y)
    );
    top$lanes$2$bilinear$ch$1$cells_q$0 cells_q$0(
        .d(cells_q$0$d),
        .q(cells_q$0$q),
        .clock(cells_q$0$clock)
    );
    top$lanes$2$bilinear$ch$1$cells_q$1 cells_q$1(
        .d(cells_q$1$d),
        .q(cells_q$1$q),
        .clock(cells_q$1$clock)
    );
    top$lanes$2$bilinear$ch$1$cells_q$2 cells_q$2(
        .d(cells_q$2$d),
        .q(cells_q$2$q),
        .clock(cells_q$2$clock)
    );
    top$lanes$2$bilinear$ch$1$cells_q$3 cells_q$3(
        .d(cells_q$3$d),
        .q(cells_q$3$q),
        .clock(cells_q$3$clock)
    );
    
    // Update code
    always @(*) begin
        cells_q$0$clock = clock;
        cells_q$1$clock = clock;
        cells_q$2$clock = clock;
        cells_q$3$clock = clock;
        top$clock = clock;
        bottom$clock = clock;
        vertical$clock = clock;
        cells_q$0$d = c00;
        cells_q$1$d = c10;
        cells_q$2$d = c01;
        cells_q$3$d = c11;
        top$a = cells_q$0$q;
        top$b = cells_q$1$q;
        top$w = wx;
        bottom$a = cells_q$2$q;
        bottom$b = cells_q$3$q;
        bottom$w = wx;
        vertical$a = top$y;
        vertical$b = bottom$y;
        vertical$w = wy;
        y = vertical$y;
    end
    
endmodule // top$lanes$2$bilinear$ch$1
module top$lanes$2$bilinear$ch$1$bottom(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$lanes$2$bilinear$ch$1$bottom$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$lanes$2$bilinear$ch$1$bottom$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$lanes$2$bilinear$ch$1$bottom$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$lanes$2$bilinear$ch$1$bottom$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$lanes$2$bilinear$ch$1$bottom$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$lanes$2$bilinear$ch$1$bottom$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$lanes$2$bilinear$ch$1$bottom$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$lanes$2$bilinear$ch$1$bottom$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$lanes$2$bilinear$ch$1$bottom$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$lanes$2$bilinear$ch$1$bottom
module top$lanes$2$bilinear$ch$1$bottom$a_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$1$bottom$a_q
module top$lanes$2$bilinear$ch$1$bottom$a_q2(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$1$bottom$a_q2
module top$lanes$2$bilinear$ch$1$bottom$diff_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$1$bottom$diff_q
module top$lanes$2$bilinear$ch$1$bottom$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$lanes$2$bilinear$ch$1$bottom$narrow
module top$lanes$2$bilinear$ch$1$bottom$prod_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$1$bottom$prod_q
module top$lanes$2$bilinear$ch$1$bottom$up_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$1$bottom$up_q
module top$lanes$2$bilinear$ch$1$bottom$up_q2(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$1$bottom$up_q2
module top$lanes$2$bilinear$ch$1$bottom$w_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$1$bottom$w_q
module top$lanes$2$bilinear$ch$1$bottom$y_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$1$bottom$y_q
module top$lanes$2$bilinear$ch$1$cells_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$1$cells_q$0
module top$lanes$2$bilinear$ch$1$cells_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$1$cells_q$1
module top$lanes$2$bilinear$ch$1$cells_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$1$cells_q$2
module top$lanes$2$bilinear$ch$1$cells_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$1$cells_q$3
module top$lanes$2$bilinear$ch$1$top(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$lanes$2$bilinear$ch$1$top$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$lanes$2$bilinear$ch$1$top$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$lanes$2$bilinear$ch$1$top$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$lanes$2$bilinear$ch$1$top$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$lanes$2$bilinear$ch$1$top$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$lanes$2$bilinear$ch$1$top$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$lanes$2$bilinear$ch$1$top$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$lanes$2$bilinear$ch$1$top$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$lanes$2$bilinear$ch$1$top$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$lanes$2$bilinear$ch$1$top
module top$lanes$2$bilinear$ch$1$top$a_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$1$top$a_q
module top$lanes$2$bilinear$ch$1$top$a_q2(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$1$top$a_q2
module top$lanes$2$bilinear$ch$1$top$diff_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$1$top$diff_q
module top$lanes$2$bilinear$ch$1$top$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$lanes$2$bilinear$ch$1$top$narrow
module top$lanes$2$bilinear$ch$1$top$prod_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$1$top$prod_q
module top$lanes$2$bilinear$ch$1$top$up_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$1$top$up_q
module top$lanes$2$bilinear$ch$1$top$up_q2(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$1$top$up_q2
module top$lanes$2$bilinear$ch$1$top$w_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$1$top$w_q
module top$lanes$2$bilinear$ch$1$top$y_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$1$top$y_q
module top$lanes$2$bilinear$ch$1$vertical(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$lanes$2$bilinear$ch$1$vertical$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$lanes$2$bilinear$ch$1$vertical$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$lanes$2$bilinear$ch$1$vertical$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$lanes$2$bilinear$ch$1$vertical$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$lanes$2$bilinear$ch$1$vertical$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$lanes$2$bilinear$ch$1$vertical$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$lanes$2$bilinear$ch$1$vertical$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$lanes$2$bilinear$ch$1$vertical$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$lanes$2$bilinear$ch$1$vertical$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$lanes$2$bilinear$ch$1$vertical
module top$lanes$2$bilinear$ch$1$vertical$a_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$1$vertical$a_q
module top$lanes$2$bilinear$ch$1$vertical$a_q2(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$1$vertical$a_q2
module top$lanes$2$bilinear$ch$1$vertical$diff_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$1$vertical$diff_q
module top$lanes$2$bilinear$ch$1$vertical$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$lanes$2$bilinear$ch$1$vertical$narrow
module top$lanes$2$bilinear$ch$1$vertical$prod_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$1$vertical$prod_q
module top$lanes$2$bilinear$ch$1$vertical$up_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$1$vertical$up_q
module top$lanes$2$bilinear$ch$1$vertical$up_q2(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$1$vertical$up_q2
module top$lanes$2$bilinear$ch$1$vertical$w_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$1$vertical$w_q
module top$lanes$2$bilinear$ch$1$vertical$y_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$1$vertical$y_q
module top$lanes$2$bilinear$ch$2(clock,c00,c10,c01,c11,wx,wy,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] c00;
    input wire  [31:0] c10;
    input wire  [31:0] c01;
    input wire  [31:0] c11;
    input wire  [15:0] wx;
    input wire  [15:0] wy;
    output reg  [31:0] y;
    
    // Stub signals
    reg  top$clock;
    reg  [31:0] top$a;
    reg  [31:0] top$b;
    reg  [15:0] top$w;
    wire  [31:0] top$y;
    reg  bottom$clock;
    reg  [31:0] bottom$a;
    reg  [31:0] bottom$b;
    reg  [15:0] bottom$w;
    wire  [31:0] bottom$y;
    reg  vertical$clock;
    reg  [31:0] vertical$a;
    reg  [31:0] vertical$b;
    reg  [15:0] vertical$w;
    wire  [31:0] vertical$y;
    reg  [31:0] cells_q$0$d;
    wire  [31:0] cells_q$0$q;
    reg  cells_q$0$clock;
    reg  [31:0] cells_q$1$d;
    wire  [31:0] cells_q$1$q;
    reg  cells_q$1$clock;
    reg  [31:0] cells_q$2$d;
    wire  [31:0] cells_q$2$q;
    reg  cells_q$2$clock;
    reg  [31:0] cells_q$3$d;
    wire  [31:0] cells_q$3$q;
    reg  cells_q$3$clock;
    
    // Sub module instances
    top$lanes$2$bilinear$ch$2$top top(
        .clock(top$clock),
        .a(top$a),
        .b(top$b),
        .w(top$w),
        .y(top$y)
    );
    top$lanes$2$bilinear$ch$2$bottom bottom(
        .clock(bottom$clock),
        .a(bottom$a),
        .b(bottom$b),
        .w(bottom$w),
        .y(bottom$y)
    );
    top$lanes$2$bilinear$ch$2$vertical vertical(
        .clock(vertical$clock),
        .a(vertical$a),
        .b(vertical$b),
        .w(vertical$w),
        .y(vertical$y)
    );
    top$lanes$2$bilinear$ch$2$cells_q$0 cells_q$0(
        .d(cells_q$0$d),
        .q(cells_q$0$q),
        .clock(cells_q$0$clock)
    );
    top$lanes$2$bilinear$ch$2$cells_q$1 cells_q$1(
        .d(cells_q$1$d),
        .q(cells_q$1$q),
        .clock(cells_q$1$clock)
    );
    top$lanes$2$bilinear$ch$2$cells_q$2 cells_q$2(
        .d(cells_q$2$d),
        .q(cells_q$2$q),
        .clock(cells_q$2$clock)
    );
    top$lanes$2$bilinear$ch$2$cells_q$3 cells_q$3(
        .d(cells_q$3$d),
        .q(cells_q$3$q),
        .clock(cells_q$3$clock)
    );
    
    // Update code
    always @(*) begin
        cells_q$0$clock = clock;
        cells_q$1$clock = clock;
        cells_q$2$clock = clock;
        cells_q$3$clock = clock;
        top$clock = clock;
        bottom$clock = clock;
        vertical$clock = clock;
        cells_q$0$d = c00;
        cells_q$1$d = c10;
        cells_q$2$d = c01;
        cells_q$3$d = c11;
        top$a = cells_q$0$q;
        top$b = cells_q$1$q;
        top$w = wx;
        bottom$a = cells_q$2$q;
        bottom$b = cells_q$3$q;
        bottom$w = wx;
        vertical$a = top$y;
        vertical$b = bottom$y;
        vertical$w = wy;
        y = vertical$y;
    end
    
endmodule // top$lanes$2$bilinear$ch$2
module top$lanes$2$bilinear$ch$2$bottom(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$lanes$2$bilinear$ch$2$bottom$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$lanes$2$bilinear$ch$2$bottom$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$lanes$2$bilinear$ch$2$bottom$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$lanes$2$bilinear$ch$2$bottom$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$lanes$2$bilinear$ch$2$bottom$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$lanes$2$bilinear$ch$2$bottom$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$lanes$2$bilinear$ch$2$bottom$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$lanes$2$bilinear$ch$2$bottom$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$lanes$2$bilinear$ch$2$bottom$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$lanes$2$bilinear$ch$2$bottom
module top$lanes$2$bilinear$ch$2$bottom$a_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$2$bottom$a_q
module top$lanes$2$bilinear$ch$2$bottom$a_q2(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$2$bottom$a_q2
module top$lanes$2$bilinear$ch$2$bottom$diff_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$2$bottom$diff_q
module top$lanes$2$bilinear$ch$2$bottom$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$lanes$2$bilinear$ch$2$bottom$narrow
module top$lanes$2$bilinear$ch$2$bottom$prod_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$2$bottom$prod_q
module top$lanes$2$bilinear$ch$2$bottom$up_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$2$bottom$up_q
module top$lanes$2$bilinear$ch$2$bottom$up_q2(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$2$bottom$up_q2
module top$lanes$2$bilinear$ch$2$bottom$w_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$2$bottom$w_q
module top$lanes$2$bilinear$ch$2$bottom$y_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$2$bottom$y_q
module top$lanes$2$bilinear$ch$2$cells_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$2$cells_q$0
module top$lanes$2$bilinear$ch$2$cells_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$2$cells_q$1
module top$lanes$2$bilinear$ch$2$cells_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$2$cells_q$2
module top$lanes$2$bilinear$ch$2$cells_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$2$cells_q$3
module top$lanes$2$bilinear$ch$2$top(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$lanes$2$bilinear$ch$2$top$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$lanes$2$bilinear$ch$2$top$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$lanes$2$bilinear$ch$2$top$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$lanes$2$bilinear$ch$2$top$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$lanes$2$bilinear$ch$2$top$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$lanes$2$bilinear$ch$2$top$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$lanes$2$bilinear$ch$2$top$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$lanes$2$bilinear$ch$2$top$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$lanes$2$bilinear$ch$2$top$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$lanes$2$bilinear$ch$2$top
module top$lanes$2$bilinear$ch$2$top$a_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$2$top$a_q
module top$lanes$2$bilinear$ch$2$top$a_q2(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$2$top$a_q2
module top$lanes$2$bilinear$ch$2$top$diff_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$2$top$diff_q
module top$lanes$2$bilinear$ch$2$top$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$lanes$2$bilinear$ch$2$top$narrow
module top$lanes$2$bilinear$ch$2$top$prod_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$2$top$prod_q
module top$lanes$2$bilinear$ch$2$top$up_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$2$top$up_q
module top$lanes$2$bilinear$ch$2$top$up_q2(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$2$top$up_q2
module top$lanes$2$bilinear$ch$2$top$w_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$2$top$w_q
module top$lanes$2$bilinear$ch$2$top$y_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$2$top$y_q
module top$lanes$2$bilinear$ch$2$vertical(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$lanes$2$bilinear$ch$2$vertical$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$lanes$2$bilinear$ch$2$vertical$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$lanes$2$bilinear$ch$2$vertical$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$lanes$2$bilinear$ch$2$vertical$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$lanes$2$bilinear$ch$2$vertical$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$lanes$2$bilinear$ch$2$vertical$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$lanes$2$bilinear$ch$2$vertical$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$lanes$2$bilinear$ch$2$vertical$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$lanes$2$bilinear$ch$2$vertical$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$lanes$2$bilinear$ch$2$vertical
module top$lanes$2$bilinear$ch$2$vertical$a_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$2$vertical$a_q
module top$lanes$2$bilinear$ch$2$vertical$a_q2(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$2$vertical$a_q2
module top$lanes$2$bilinear$ch$2$vertical$diff_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$2$vertical$diff_q
module top$lanes$2$bilinear$ch$2$vertical$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$lanes$2$bilinear$ch$2$vertical$narrow
module top$lanes$2$bilinear$ch$2$vertical$prod_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$2$vertical$prod_q
module top$lanes$2$bilinear$ch$2$vertical$up_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$2$vertical$up_q
module top$lanes$2$bilinear$ch$2$vertical$up_q2(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$2$vertical$up_q2
module top$lanes$2$bilinear$ch$2$vertical$w_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$2$vertical$w_q
module top$lanes$2$bilinear$ch$2$vertical$y_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$2$vertical$y_q
module top$lanes$2$bilinear$ch$3(clock,c00,c10,c01,c11,wx,wy,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] c00;
    input wire  [31:0] c10;
    input wire  [31:0] c01;
    input wire  [31:0] c11;
    input wire  [15:0] wx;
    input wire  [15:0] wy;
    output reg  [31:0] y;
    
    // Stub signals
    reg  top$clock;
    reg  [31:0] top$a;
    reg  [31:0] top$b;
    reg  [15:0] top$w;
    wire  [31:0] top$y;
    reg  bottom$clock;
    reg  [31:0] bottom$a;
    reg  [31:0] bottom$b;
    reg  [15:0] bottom$w;
    wire  [31:0] bottom$y;
    reg  vertical$clock;
    reg  [31:0] vertical$a;
    reg  [31:0] vertical$b;
    reg  [15:0] vertical$w;
    wire  [31:0] vertical$y;
    reg  [31:0] cells_q$0$d;
    wire  [31:0] cells_q$0$q;
    reg  cells_q$0$clock;
    reg  [31:0] cells_q$1$d;
    wire  [31:0] cells_q$1$q;
    reg  cells_q$1$clock;
    reg  [31:0] cells_q$2$d;
    wire  [31:0] cells_q$2$q;
    reg  cells_q$2$clock;
    reg  [31:0] cells_q$3$d;
    wire  [31:0] cells_q$3$q;
    reg  cells_q$3$clock;
    
    // Sub module instances
    top$lanes$2$bilinear$ch$3$top top(
        .clock(top$clock),
        .a(top$a),
        .b(top$b),
        .w(top$w),
        .y(top$y)
    );
    top$lanes$2$bilinear$ch$3$bottom bottom(
        .clock(bottom$clock),
        .a(bottom$a),
        .b(bottom$b),
        .w(bottom$w),
        .y(bottom$y)
    );
    top$lanes$2$bilinear$ch$3$vertical vertical(
        .clock(vertical$clock),
        .a(vertical$a),
        .b(vertical$b),
        .w(vertical$w),
        .y(vertical$y)
    );
    top$lanes$2$bilinear$ch$3$cells_q$0 cells_q$0(
        .d(cells_q$0$d),
        .q(cells_q$0$q),
        .clock(cells_q$0$clock)
    );
    top$lanes$2$bilinear$ch$3$cells_q$1 cells_q$1(
        .d(cells_q$1$d),
        .q(cells_q$1$q),
        .clock(cells_q$1$clock)
    );
    top$lanes$2$bilinear$ch$3$cells_q$2 cells_q$2(
        .d(cells_q$2$d),
        .q(cells_q$2$q),
        .clock(cells_q$2$clock)
    );
    top$lanes$2$bilinear$ch$3$cells_q$3 cells_q$3(
        .d(cells_q$3$d),
        .q(cells_q$3$q),
        .clock(cells_q$3$clock)
    );
    
    // Update code
    always @(*) begin
        cells_q$0$clock = clock;
        cells_q$1$clock = clock;
        cells_q$2$clock = clock;
        cells_q$3$clock = clock;
        top$clock = clock;
        bottom$clock = clock;
        vertical$clock = clock;
        cells_q$0$d = c00;
        cells_q$1$d = c10;
        cells_q$2$d = c01;
        cells_q$3$d = c11;
        top$a = cells_q$0$q;
        top$b = cells_q$1$q;
        top$w = wx;
        bottom$a = cells_q$2$q;
        bottom$b = cells_q$3$q;
        bottom$w = wx;
        vertical$a = top$y;
        vertical$b = bottom$y;
        vertical$w = wy;
        y = vertical$y;
    end
    
endmodule // top$lanes$2$bilinear$ch$3
module top$lanes$2$bilinear$ch$3$bottom(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$lanes$2$bilinear$ch$3$bottom$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$lanes$2$bilinear$ch$3$bottom$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$lanes$2$bilinear$ch$3$bottom$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$lanes$2$bilinear$ch$3$bottom$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$lanes$2$bilinear$ch$3$bottom$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$lanes$2$bilinear$ch$3$bottom$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$lanes$2$bilinear$ch$3$bottom$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$lanes$2$bilinear$ch$3$bottom$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$lanes$2$bilinear$ch$3$bottom$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$lanes$2$bilinear$ch$3$bottom
module top$lanes$2$bilinear$ch$3$bottom$a_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$3$bottom$a_q
module top$lanes$2$bilinear$ch$3$bottom$a_q2(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$3$bottom$a_q2
module top$lanes$2$bilinear$ch$3$bottom$diff_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$3$bottom$diff_q
module top$lanes$2$bilinear$ch$3$bottom$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$lanes$2$bilinear$ch$3$bottom$narrow
module top$lanes$2$bilinear$ch$3$bottom$prod_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$3$bottom$prod_q
module top$lanes$2$bilinear$ch$3$bottom$up_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$3$bottom$up_q
module top$lanes$2$bilinear$ch$3$bottom$up_q2(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$3$bottom$up_q2
module top$lanes$2$bilinear$ch$3$bottom$w_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$3$bottom$w_q
module top$lanes$2$bilinear$ch$3$bottom$y_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$3$bottom$y_q
module top$lanes$2$bilinear$ch$3$cells_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$3$cells_q$0
module top$lanes$2$bilinear$ch$3$cells_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$3$cells_q$1
module top$lanes$2$bilinear$ch$3$cells_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$3$cells_q$2
module top$lanes$2$bilinear$ch$3$cells_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$3$cells_q$3
module top$lanes$2$bilinear$ch$3$top(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$lanes$2$bilinear$ch$3$top$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$lanes$2$bilinear$ch$3$top$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$lanes$2$bilinear$ch$3$top$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$lanes$2$bilinear$ch$3$top$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$lanes$2$bilinear$ch$3$top$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$lanes$2$bilinear$ch$3$top$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$lanes$2$bilinear$ch$3$top$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$lanes$2$bilinear$ch$3$top$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$lanes$2$bilinear$ch$3$top$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$lanes$2$bilinear$ch$3$top
module top$lanes$2$bilinear$ch$3$top$a_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$3$top$a_q
module top$lanes$2$bilinear$ch$3$top$a_q2(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$3$top$a_q2
module top$lanes$2$bilinear$ch$3$top$diff_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$3$top$diff_q
module top$lanes$2$bilinear$ch$3$top$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$lanes$2$bilinear$ch$3$top$narrow
module top$lanes$2$bilinear$ch$3$top$prod_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$3$top$prod_q
module top$lanes$2$bilinear$ch$3$top$up_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$3$top$up_q
module top$lanes$2$bilinear$ch$3$top$up_q2(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$3$top$up_q2
module top$lanes$2$bilinear$ch$3$top$w_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$3$top$w_q
module top$lanes$2$bilinear$ch$3$top$y_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$3$top$y_q
module top$lanes$2$bilinear$ch$3$vertical(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$lanes$2$bilinear$ch$3$vertical$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$lanes$2$bilinear$ch$3$vertical$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$lanes$2$bilinear$ch$3$vertical$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$lanes$2$bilinear$ch$3$vertical$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$lanes$2$bilinear$ch$3$vertical$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$lanes$2$bilinear$ch$3$vertical$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$lanes$2$bilinear$ch$3$vertical$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$lanes$2$bilinear$ch$3$vertical$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$lanes$2$bilinear$ch$3$vertical$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$lanes$2$bilinear$ch$3$vertical
module top$lanes$2$bilinear$ch$3$vertical$a_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$3$vertical$a_q
module top$lanes$2$bilinear$ch$3$vertical$a_q2(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$3$vertical$a_q2
module top$lanes$2$bilinear$ch$3$vertical$diff_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$3$vertical$diff_q
module top$lanes$2$bilinear$ch$3$vertical$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$lanes$2$bilinear$ch$3$vertical$narrow
module top$lanes$2$bilinear$ch$3$vertical$prod_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$3$vertical$prod_q
module top$lanes$2$bilinear$ch$3$vertical$up_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$3$vertical$up_q
module top$lanes$2$bilinear$ch$3$vertical$up_q2(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$3$vertical$up_q2
module top$lanes$2$bilinear$ch$3$vertical$w_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$3$vertical$w_q
module top$lanes$2$bilinear$ch$3$vertical$y_q(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$ch$3$vertical$y_q
module top$lanes$2$bilinear$wx_q$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$2$bilinear$wx_q$0
module top$lanes$2$bilinear$wx_q$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$2$bilinear$wx_q$1
module top$lanes$2$bilinear$wx_q$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$2$bilinear$wx_q$2
module top$lanes$2$bilinear$wx_q$3(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$2$bilinear$wx_q$3
module top$lanes$2$bilinear$wy_last$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$2$bilinear$wy_last$0
module top$lanes$2$bilinear$wy_last$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$2$bilinear$wy_last$1
module top$lanes$2$bilinear$wy_last$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$2$bilinear$wy_last$2
module top$lanes$2$bilinear$wy_last$3(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$2$bilinear$wy_last$3
module top$lanes$2$bilinear$wy_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$wy_q$0
module top$lanes$2$bilinear$wy_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$wy_q$1
module top$lanes$2$bilinear$wy_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$2$bilinear$wy_q$2
module top$lanes$3$bilinear(clock,c00$0,c00$1,c00$2,c00$3,c10$0,c10$1,c10$2,c10$3,c01$0,c01$1,c01$2,c01$3,c11$0,c11$1,c11$2,c11$3,wx,wy,out$0,out$1,out$2,out$3);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] c00$0;
    input wire  [31:0] c00$1;
    input wire  [31:0] c00$2;
    input wire  [31:0] c00$3;
    input wire  [31:0] c10$0;
    input wire  [31:0] c10$1;
    input wire  [31:0] c10$2;
    input wire  [31:0] c10$3;
    input wire  [31:0] c01$0;
    input wire  [31:0] c01$1;
    input wire  [31:0] c01$2;
    input wire  [31:0] c01$3;
    input wire  [31:0] c11$0;
    input wire  [31:0] c11$1;
    input wire  [31:0] c11$2;
    input wire  [31:0] c11$3;
    input wire  [15:0] wx;
    input wire  [15:0] wy;
    output reg  [31:0] out$0;
    output reg  [31:0] out$1;
    output reg  [31:0] out$2;
    output reg  [31:0] out$3;
    
    // Stub signals
    reg  [15:0] wx_q$0$d;
    wire  [15:0] wx_q$0$q;
    reg  wx_q$0$clock;
    reg  [15:0] wx_q$1$d;
    wire  [15:0] wx_q$1$q;
    reg  wx_q$1$clock;
    reg  [15:0] wx_q$2$d;
    wire  [15:0] wx_q$2$q;
    reg  wx_q$2$clock;
    reg  [15:0] wx_q$3$d;
    wire  [15:0] wx_q$3$q;
    reg  wx_q$3$clock;
    reg  [15:0] wy_q$0$d;
    wire  [15:0] wy_q$0$q;
    reg  wy_q$0$clock;
    reg  [15:0] wy_q$1$d;
    wire  [15:0] wy_q$1$q;
    reg  wy_q$1$clock;
    reg  [15:0] wy_q$2$d;
    wire  [15:0] wy_q$2$q;
    reg  wy_q$2$clock;
    reg  [15:0] wy_last$0$d;
    wire  [15:0] wy_last$0$q;
    reg  wy_last$0$clock;
    reg  [15:0] wy_last$1$d;
    wire  [15:0] wy_last$1$q;
    reg  wy_last$1$clock;
    reg  [15:0] wy_last$2$d;
    wire  [15:0] wy_last$2$q;
    reg  wy_last$2$clock;
    reg  [15:0] wy_last$3$d;
    wire  [15:0] wy_last$3$q;
    reg  wy_last$3$clock;
    reg  ch$0$clock;
    reg  [31:0] ch$0$c00;
    reg  [31:0] ch$0$c10;
    reg  [31:0] ch$0$c01;
    reg  [31:0] ch$0$c11;
    reg  [15:0] ch$0$wx;
    reg  [15:0] ch$0$wy;
    wire  [31:0] ch$0$y;
    reg  ch$1$clock;
    reg  [31:0] ch$1$c00;
    reg  [31:0] ch$1$c10;
    reg  [31:0] ch$1$c01;
    reg  [31:0] ch$1$c11;
    reg  [15:0] ch$1$wx;
    reg  [15:0] ch$1$wy;
    wire  [31:0] ch$1$y;
    reg  ch$2$clock;
    reg  [31:0] ch$2$c00;
    reg  [31:0] ch$2$c10;
    reg  [31:0] ch$2$c01;
    reg  [31:0] ch$2$c11;
    reg  [15:0] ch$2$wx;
    reg  [15:0] ch$2$wy;
    wire  [31:0] ch$2$y;
    reg  ch$3$clock;
    reg  [31:0] ch$3$c00;
    reg  [31:0] ch$3$c10;
    reg  [31:0] ch$3$c01;
    reg  [31:0] ch$3$c11;
    reg  [15:0] ch$3$wx;
    reg  [15:0] ch$3$wy;
    wire  [31:0] ch$3$y;
    
    // Sub module instances
    top$lanes$3$bilinear$wx_q$0 wx_q$0(
        .d(wx_q$0$d),
        .q(wx_q$0$q),
        .clock(wx_q$0$clock)
    );
    top$lanes$3$bilinear$wx_q$1 wx_q$1(
        .d(wx_q$1$d),
        .q(wx_q$1$q),
        .clock(wx_q$1$clock)
    );
    top$lanes$3$bilinear$wx_q$2 wx_q$2(
        .d(wx_q$2$d),
        .q(wx_q$2$q),
        .clock(wx_q$2$clock)
    );
    top$lanes$3$bilinear$wx_q$3 wx_q$3(
        .d(wx_q$3$d),
        .q(wx_q$3$q),
        .clock(wx_q$3$clock)
    );
    top$lanes$3$bilinear$wy_q$0 wy_q$0(
        .d(wy_q$0$d),
        .q(wy_q$0$q),
        .clock(wy_q$0$clock)
    );
    top$lanes$3$bilinear$wy_q$1 wy_q$1(
        .d(wy_q$1$d),
        .q(wy_q$1$q),
        .clock(wy_q$1$clock)
    );
    top$lanes$3$bilinear$wy_q$2 wy_q$2(
        .d(wy_q$2$d),
        .q(wy_q$2$q),
        .clock(wy_q$2$clock)
    );
    top$lanes$3$bilinear$wy_last$0 wy_last$0(
        .d(wy_last$0$d),
        .q(wy_last$0$q),
        .clock(wy_last$0$clock)
    );
    top$lanes$3$bilinear$wy_last$1 wy_last$1(
        .d(wy_last$1$d),
        .q(wy_last$1$q),
        .clock(wy_last$1$clock)
    );
    top$lanes$3$bilinear$wy_last$2 wy_last$2(
        .d(wy_last$2$d),
        .q(wy_last$2$q),
        .clock(wy_last$2$clock)
    );
    top$lanes$3$bilinear$wy_last$3 wy_last$3(
        .d(wy_last$3$d),
        .q(wy_last$3$q),
        .clock(wy_last$3$clock)
    );
    top$lanes$3$bilinear$ch$0 ch$0(
        .clock(ch$0$clock),
        .c00(ch$0$c00),
        .c10(ch$0$c10),
        .c01(ch$0$c01),
        .c11(ch$0$c11),
        .wx(ch$0$wx),
        .wy(ch$0$wy),
        .y(ch$0$y)
    );
    top$lanes$3$bilinear$ch$1 ch$1(
        .clock(ch$1$clock),
        .c00(ch$1$c00),
        .c10(ch$1$c10),
        .c01(ch$1$c01),
        .c11(ch$1$c11),
        .wx(ch$1$wx),
        .wy(ch$1$wy),
        .y(ch$1$y)
    );
    top$lanes$3$bilinear$ch$2 ch$2(
        .clock(ch$2$clock),
        .c00(ch$2$c00),
        .c10(ch$2$c10),
        .c01(ch$2$c01),
        .c11(ch$2$c11),
        .wx(ch$2$wx),
        .wy(ch$2$wy),
        .y(ch$2$y)
    );
    top$lanes$3$bilinear$ch$3 ch$3(
        .clock(ch$3$clock),
        .c00(ch$3$c00),
        .c10(ch$3$c10),
        .c01(ch$3$c01),
        .c11(ch$3$c11),
        .wx(ch$3$wx),
        .wy(ch$3$wy),
        .y(ch$3$y)
    );
    
    // Update code
    always @(*) begin
        wy_q$0$clock = clock;
        wy_q$1$clock = clock;
        wy_q$2$clock = clock;
        wy_q$0$d = wy;
        wy_q$1$d = wy_q$0$q;
        wy_q$2$d = wy_q$1$q;
        wx_q$0$clock = clock;
        wx_q$0$d = wx;
        wy_last$0$clock = clock;
        wy_last$0$d = wy_q$2$q;
        ch$0$clock = clock;
        ch$0$c00 = c00$0;
        ch$0$c10 = c10$0;
        ch$0$c01 = c01$0;
        ch$0$c11 = c11$0;
        ch$0$wx = wx_q$0$q;
        ch$0$wy = wy_last$0$q;
        out$0 = ch$0$y;
        wx_q$1$clock = clock;
        wx_q$1$d = wx;
        wy_last$1$clock = clock;
        wy_last$1$d = wy_q$2$q;
        ch$1$clock = clock;
        ch$1$c00 = c00$1;
        ch$1$c10 = c10$1;
        ch$1$c01 = c01$1;
        ch$1$c11 = c11$1;
        ch$1$wx = wx_q$1$q;
        ch$1$wy = wy_last$1$q;
        out$1 = ch$1$y;
        wx_q$2$clock = clock;
        wx_q$2$d = wx;
        wy_last$2$clock = clock;
        wy_last$2$d = wy_q$2$q;
        ch$2$clock = clock;
        ch$2$c00 = c00$2;
        ch$2$c10 = c10$2;
        ch$2$c01 = c01$2;
        ch$2$c11 = c11$2;
        ch$2$wx = wx_q$2$q;
        ch$2$wy = wy_last$2$q;
        out$2 = ch$2$y;
        wx_q$3$clock = clock;
        wx_q$3$d = wx;
        wy_last$3$clock = clock;
        wy_last$3$d = wy_q$2$q;
        ch$3$clock = clock;
        ch$3$c00 = c00$3;
        ch$3$c10 = c10$3;
        ch$3$c01 = c01$3;
        ch$3$c11 = c11$3;
        ch$3$wx = wx_q$3$q;
        ch$3$wy = wy_last$3$q;
        out$3 = ch$3$y;
    end
    
endmodule // top$lanes$3$bilinear
module top$lanes$3$bilinear$ch$0(clock,c00,c10,c01,c11,wx,wy,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] c00;
    input wire  [31:0] c10;
    input wire  [31:0] c01;
    input wire  [31:0] c11;
    input wire  [15:0] wx;
    input wire  [15:0] wy;
    output reg  [31:0] y;
    
    // Stub signals
    reg  top$clock;
    reg  [31:0] top$a;
    reg  [31:0] top$b;
    reg  [15:0] top$w;
    wire  [31:0] top$y;
    reg  bottom$clock;
    reg  [31:0] bottom$a;
    reg  [31:0] bottom$b;
    reg  [15:0] bottom$w;
    wire  [31:0] bottom$y;
    reg  vertical$clock;
    reg  [31:0] vertical$a;
    reg  [31:0] vertical$b;
    reg  [15:0] vertical$w;
    wire  [31:0] vertical$y;
    reg  [31:0] cells_q$0$d;
    wire  [31:0] cells_q$0$q;
    reg  cells_q$0$clock;
    reg  [31:0] cells_q$1$d;
    wire  [31:0] cells_q$1$q;
    reg  cells_q$1$clock;
    reg  [31:0] cells_q$2$d;
    wire  [31:0] cells_q$2$q;
    reg  cells_q$2$clock;
    reg  [31:0] cells_q$3$d;
    wire  [31:0] cells_q$3$q;
    reg  cells_q$3$clock;
    
    // Sub module instances
    top$lanes$3$bilinear$ch$0$top top(
        .clock(top$clock),
        .a(top$a),
        .b(top$b),
        .w(top$w),
        .y(top$y)
    );
    top$lanes$3$bilinear$ch$0$bottom bottom(
        .clock(bottom$clock),
        .a(bottom$a),
        .b(bottom$b),
        .w(bottom$w),
        .y(bottom$y)
    );
    top$lanes$3$bilinear$ch$0$vertical vertical(
        .clock(vertical$clock),
        .a(vertical$a),
        .b(vertical$b),
        .w(vertical$w),
        .y(vertical$y)
    );
    top$lanes$3$bilinear$ch$0$cells_q$0 cells_q$0(
        .d(cells_q$0$d),
        .q(cells_q$0$q),
        .clock(cells_q$0$clock)
    );
    top$lanes$3$bilinear$ch$0$cells_q$1 cells_q$1(
        .d(cells_q$1$d),
        .q(cells_q$1$q),
        .clock(cells_q$1$clock)
    );
    top$lanes$3$bilinear$ch$0$cells_q$2 cells_q$2(
        .d(cells_q$2$d),
        .q(cells_q$2$q),
        .clock(cells_q$2$clock)
    );
    top$lanes$3$bilinear$ch$0$cells_q$3 cells_q$3(
        .d(cells_q$3$d),
        .q(cells_q$3$q),
        .clock(cells_q$3$clock)
    );
    
    // Update code
    always @(*) begin
        cells_q$0$clock = clock;
        cells_q$1$clock = clock;
        cells_q$2$clock = clock;
        cells_q$3$clock = clock;
        top$clock = clock;
        bottom$clock = clock;
        vertical$clock = clock;
        cells_q$0$d = c00;
        cells_q$1$d = c10;
        cells_q$2$d = c01;
        cells_q$3$d = c11;
        top$a = cells_q$0$q;
        top$b = cells_q$1$q;
        top$w = wx;
        bottom$a = cells_q$2$q;
        bottom$b = cells_q$3$q;
        bottom$w = wx;
        vertical$a = top$y;
        vertical$b = bottom$y;
        vertical$w = wy;
        y = vertical$y;
    end
    
endmodule // top$lanes$3$bilinear$ch$0
module top$lanes$3$bilinear$ch$0$bottom(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$lanes$3$bilinear$ch$0$bottom$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$lanes$3$bilinear$ch$0$bottom$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$lanes$3$bilinear$ch$0$bottom$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$lanes$3$bilinear$ch$0$bottom$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$lanes$3$bilinear$ch$0$bottom$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$lanes$3$bilinear$ch$0$bottom$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$lanes$3$bilinear$ch$0$bottom$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$lanes$3$bilinear$ch$0$bottom$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$lanes$3$bilinear$ch$0$bottom$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$lanes$3$bilinear$ch$0$bottom
module top$lanes$3$bilinear$ch$0$bottom$a_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$0$bottom$a_q
module top$lanes$3$bilinear$ch$0$bottom$a_q2(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$0$bottom$a_q2
module top$lanes$3$bilinear$ch$0$bottom$diff_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$0$bottom$diff_q
module top$lanes$3$bilinear$ch$0$bottom$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$lanes$3$bilinear$ch$0$bottom$narrow
module top$lanes$3$bilinear$ch$0$bottom$prod_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$0$bottom$prod_q
module top$lanes$3$bilinear$ch$0$bottom$up_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$0$bottom$up_q
module top$lanes$3$bilinear$ch$0$bottom$up_q2(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$0$bottom$up_q2
module top$lanes$3$bilinear$ch$0$bottom$w_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$0$bottom$w_q
module top$lanes$3$bilinear$ch$0$bottom$y_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$0$bottom$y_q
module top$lanes$3$bilinear$ch$0$cells_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$0$cells_q$0
module top$lanes$3$bilinear$ch$0$cells_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$0$cells_q$1
module top$lanes$3$bilinear$ch$0$cells_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$0$cells_q$2
module top$lanes$3$bilinear$ch$0$cells_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$0$cells_q$3
module top$lanes$3$bilinear$ch$0$top(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$lanes$3$bilinear$ch$0$top$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$lanes$3$bilinear$ch$0$top$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$lanes$3$bilinear$ch$0$top$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$lanes$3$bilinear$ch$0$top$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$lanes$3$bilinear$ch$0$top$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$lanes$3$bilinear$ch$0$top$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$lanes$3$bilinear$ch$0$top$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$lanes$3$bilinear$ch$0$top$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$lanes$3$bilinear$ch$0$top$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$lanes$3$bilinear$ch$0$top
module top$lanes$3$bilinear$ch$0$top$a_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$0$top$a_q
module top$lanes$3$bilinear$ch$0$top$a_q2(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$0$top$a_q2
module top$lanes$3$bilinear$ch$0$top$diff_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$0$top$diff_q
module top$lanes$3$bilinear$ch$0$top$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$lanes$3$bilinear$ch$0$top$narrow
module top$lanes$3$bilinear$ch$0$top$prod_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$0$top$prod_q
module top$lanes$3$bilinear$ch$0$top$up_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$0$top$up_q
module top$lanes$3$bilinear$ch$0$top$up_q2(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$0$top$up_q2
module top$lanes$3$bilinear$ch$0$top$w_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$0$top$w_q
module top$lanes$3$bilinear$ch$0$top$y_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$0$top$y_q
module top$lanes$3$bilinear$ch$0$vertical(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$lanes$3$bilinear$ch$0$vertical$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$lanes$3$bilinear$ch$0$vertical$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$lanes$3$bilinear$ch$0$vertical$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$lanes$3$bilinear$ch$0$vertical$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$lanes$3$bilinear$ch$0$vertical$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$lanes$3$bilinear$ch$0$vertical$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$lanes$3$bilinear$ch$0$vertical$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$lanes$3$bilinear$ch$0$vertical$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$lanes$3$bilinear$ch$0$vertical$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$lanes$3$bilinear$ch$0$vertical
module top$lanes$3$bilinear$ch$0$vertical$a_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$0$vertical$a_q
module top$lanes$3$bilinear$ch$0$vertical$a_q2(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$0$vertical$a_q2
module top$lanes$3$bilinear$ch$0$vertical$diff_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$0$vertical$diff_q
module top$lanes$3$bilinear$ch$0$vertical$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$lanes$3$bilinear$ch$0$vertical$narrow
module top$lanes$3$bilinear$ch$0$vertical$prod_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$0$vertical$prod_q
module top$lanes$3$bilinear$ch$0$vertical$up_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$0$vertical$up_q
module top$lanes$3$bilinear$ch$0$vertical$up_q2(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$0$vertical$up_q2
module top$lanes$3$bilinear$ch$0$vertical$w_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$0$vertical$w_q
module top$lanes$3$bilinear$ch$0$vertical$y_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$0$vertical$y_q
module top$lanes$3$bilinear$ch$1(clock,c00,c10,c01,c11,wx,wy,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] c00;
    input wire  [31:0] c10;
    input wire  [31:0] c01;
    input wire  [31:0] c11;
    input wire  [15:0] wx;
    input wire  [15:0] wy;
    output reg  [31:0] y;
    
    // Stub signals
    reg  top$clock;
    reg  [31:0] top$a;
    reg  [31:0] top$b;
    reg  [15:0] top$w;
    wire  [31:0] top$y;
    reg  bottom$clock;
    reg  [31:0] bottom$a;
    reg  [31:0] bottom$b;
    reg  [15:0] bottom$w;
    wire  [31:0] bottom$y;
    reg  vertical$clock;
    reg  [31:0] vertical$a;
    reg  [31:0] vertical$b;
    reg  [15:0] vertical$w;
    wire  [31:0] vertical$y;
    reg  [31:0] cells_q$0$d;
    wire  [31:0] cells_q$0$q;
    reg  cells_q$0$clock;
    reg  [31:0] cells_q$1$d;
    wire  [31:0] cells_q$1$q;
    reg  cells_q$1$clock;
    reg  [31:0] cells_q$2$d;
    wire  [31:0] cells_q$2$q;
    reg  cells_q$2$clock;
    reg  [31:0] cells_q$3$d;
    wire  [31:0] cells_q$3$q;
    reg  cells_q$3$clock;
    
    // Sub module instances
    top$lanes$3$bilinear$ch$1$top top(
        .clock(top$clock),
        .a(top$a),
        .b(top$b),
        .w(top$w),
        .y(top$y)
    );
    top$lanes$3$bilinear$ch$1$bottom bottom(
        .clock(bottom$clock),
        .a(bottom$a),
        .b(bottom$b),
        .w(bottom$w),
        .y(bottom$y)
    );
    top$lanes$3$bilinear$ch$1$vertical vertical(
        .clock(vertical$clock),
        .a(vertical$a),
        .b(vertical$b),
        .w(vertical$w),
        .y(vertical$y)
    );
    top$lanes$3$bilinear$ch$1$cells_q$0 cells_q$0(
        .d(cells_q$0$d),
        .q(cells_q$0$q),
        .clock(cells_q$0$clock)
    );
    top$lanes$3$bilinear$ch$1$cells_q$1 cells_q$1(
        .d(cells_q$1$d),
        .q(cells_q$1$q),
        .clock(cells_q$1$clock)
    );
    top$lanes$3$bilinear$ch$1$cells_q$2 cells_q$2(
        .d(cells_q$2$d),
        .q(cells_q$2$q),
        .clock(cells_q$2$clock)
    );
    top$lanes$3$bilinear$ch$1$cells_q$3 cells_q$3(
        .d(cells_q$3$d),
        .q(cells_q$3$q),
        .clock(cells_q$3$clock)
    );
    
    // Update code
    always @(*) begin
        cells_q$0$clock = clock;
        cells_q$1$clock = clock;
        cells_q$2$clock = clock;
        cells_q$3$clock = clock;
        top$clock = clock;
        bottom$clock = clock;
        vertical$clock = clock;
        cells_q$0$d = c00;
        cells_q$1$d = c10;
        cells_q$2$d = c01;
        cells_q$3$d = c11;
        top$a = cells_q$0$q;
        top$b = cells_q$1$q;
        top$w = wx;
        bottom$a = cells_q$2$q;
        bottom$b = cells_q$3$q;
        bottom$w = wx;
        vertical$a = top$y;
        vertical$b = bottom$y;
        vertical$w = wy;
        y = vertical$y;
    end
    
endmodule // top$lanes$3$bilinear$ch$1
module top$lanes$3$bilinear$ch$1$bottom(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$lanes$3$bilinear$ch$1$bottom$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$lanes$3$bilinear$ch$1$bottom$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$lanes$3$bilinear$ch$1$bottom$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$lanes$3$bilinear$ch$1$bottom$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$lanes$3$bilinear$ch$1$bottom$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$lanes$3$bilinear$ch$1$bottom$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$lanes$3$bilinear$ch$1$bottom$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$lanes$3$bilinear$ch$1$bottom$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$lanes$3$bilinear$ch$1$bottom$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$lanes$3$bilinear$ch$1$bottom
module top$lanes$3$bilinear$ch$1$bottom$a_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$1$bottom$a_q
module top$lanes$3$bilinear$ch$1$bottom$a_q2(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$1$bottom$a_q2
module top$lanes$3$bilinear$ch$1$bottom$diff_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$1$bottom$diff_q
module top$lanes$3$bilinear$ch$1$bottom$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$lanes$3$bilinear$ch$1$bottom$narrow
module top$lanes$3$bilinear$ch$1$bottom$prod_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$1$bottom$prod_q
module top$lanes$3$bilinear$ch$1$bottom$up_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$1$bottom$up_q
module top$lanes$3$bilinear$ch$1$bottom$up_q2(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$1$bottom$up_q2
module top$lanes$3$bilinear$ch$1$bottom$w_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$1$bottom$w_q
module top$lanes$3$bilinear$ch$1$bottom$y_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$1$bottom$y_q
module top$lanes$3$bilinear$ch$1$cells_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$1$cells_q$0
module top$lanes$3$bilinear$ch$1$cells_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$1$cells_q$1
module top$lanes$3$bilinear$ch$1$cells_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$1$cells_q$2
module top$lanes$3$bilinear$ch$1$cells_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$1$cells_q$3
module top$lanes$3$bilinear$ch$1$top(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$lanes$3$bilinear$ch$1$top$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$lanes$3$bilinear$ch$1$top$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$lanes$3$bilinear$ch$1$top$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$lanes$3$bilinear$ch$1$top$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$lanes$3$bilinear$ch$1$top$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$lanes$3$bilinear$ch$1$top$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$lanes$3$bilinear$ch$1$top$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$lanes$3$bilinear$ch$1$top$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$lanes$3$bilinear$ch$1$top$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$lanes$3$bilinear$ch$1$top
module top$lanes$3$bilinear$ch$1$top$a_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$1$top$a_q
module top$lanes$3$bilinear$ch$1$top$a_q2(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$1$top$a_q2
module top$lanes$3$bilinear$ch$1$top$diff_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$1$top$diff_q
module top$lanes$3$bilinear$ch$1$top$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$lanes$3$bilinear$ch$1$top$narrow
module top$lanes$3$bilinear$ch$1$top$prod_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$1$top$prod_q
module top$lanes$3$bilinear$ch$1$top$up_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$1$top$up_q
module top$lanes$3$bilinear$ch$1$top$up_q2(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$1$top$up_q2
module top$lanes$3$bilinear$ch$1$top$w_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$1$top$w_q
module top$lanes$3$bilinear$ch$1$top$y_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$1$top$y_q
module top$lanes$3$bilinear$ch$1$vertical(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$lanes$3$bilinear$ch$1$vertical$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$lanes$3$bilinear$ch$1$vertical$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$lanes$3$bilinear$ch$1$vertical$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$lanes$3$bilinear$ch$1$vertical$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$lanes$3$bilinear$ch$1$vertical$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$lanes$3$bilinear$ch$1$vertical$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$lanes$3$bilinear$ch$1$vertical$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$lanes$3$bilinear$ch$1$vertical$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$lanes$3$bilinear$ch$1$vertical$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$lanes$3$bilinear$ch$1$vertical
module top$lanes$3$bilinear$ch$1$vertical$a_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$1$vertical$a_q
module top$lanes$3$bilinear$ch$1$vertical$a_q2(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$1$vertical$a_q2
module top$lanes$3$bilinear$ch$1$vertical$diff_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$1$vertical$diff_q
module top$lanes$3$bilinear$ch$1$vertical$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$lanes$3$bilinear$ch$1$vertical$narrow
module top$lanes$3$bilinear$ch$1$vertical$prod_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$1$vertical$prod_q
module top$lanes$3$bilinear$ch$1$vertical$up_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$1$vertical$up_q
module top$lanes$3$bilinear$ch$1$vertical$up_q2(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$1$vertical$up_q2
module top$lanes$3$bilinear$ch$1$vertical$w_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$1$vertical$w_q
module top$lanes$3$bilinear$ch$1$vertical$y_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$1$vertical$y_q
module top$lanes$3$bilinear$ch$2(clock,c00,c10,c01,c11,wx,wy,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] c00;
    input wire  [31:0] c10;
    input wire  [31:0] c01;
    input wire  [31:0] c11;
    input wire  [15:0] wx;
    input wire  [15:0] wy;
    output reg  [31:0] y;
    
    // Stub signals
    reg  top$clock;
    reg  [31:0] top$a;
    reg  [31:0] top$b;
    reg  [15:0] top$w;
    wire  [31:0] top$y;
    reg  bottom$clock;
    reg  [31:0] bottom$a;
    reg  [31:0] bottom$b;
    reg  [15:0] bottom$w;
    wire  [31:0] bottom$y;
    reg  vertical$clock;
    reg  [31:0] vertical$a;
    reg  [31:0] vertical$b;
    reg  [15:0] vertical$w;
    wire  [31:0] vertical$y;
    reg  [31:0] cells_q$0$d;
    wire  [31:0] cells_q$0$q;
    reg  cells_q$0$clock;
    reg  [31:0] cells_q$1$d;
    wire  [31:0] cells_q$1$q;
    reg  cells_q$1$clock;
    reg  [31:0] cells_q$2$d;
    wire  [31:0] cells_q$2$q;
    reg  cells_q$2$clock;
    reg  [31:0] cells_q$3$d;
    wire  [31:0] cells_q$3$q;
    reg  cells_q$3$clock;
    
    // Sub module instances
    top$lanes$3$bilinear$ch$2$top top(
        .clock(top$clock),
        .a(top$a),
        .b(top$b),
        .w(top$w),
        .y(top$y)
    );
    top$lanes$3$bilinear$ch$2$bottom bottom(
        .clock(bottom$clock),
        .a(bottom$a),
        .b(bottom$b),
        .w(bottom$w),
        .y(bottom$y)
    );
    top$lanes$3$bilinear$ch$2$vertical vertical(
        .clock(vertical$clock),
        .a(vertical$a),
        .b(vertical$b),
        .w(vertical$w),
        .y(vertical$y)
    );
    top$lanes$3$bilinear$ch$2$cells_q$0 cells_q$0(
        .d(cells_q$0$d),
        .q(cells_q$0$q),
        .clock(cells_q$0$clock)
    );
    top$lanes$3$bilinear$ch$2$cells_q$1 cells_q$1(
        .d(cells_q$1$d),
        .q(cells_q$1$q),
        .clock(cells_q$1$clock)
    );
    top$lanes$3$bilinear$ch$2$cells_q$2 cells_q$2(
        .d(cells_q$2$d),
        .q(cells_q$2$q),
        .clock(cells_q$2$clock)
    );
    top$lanes$3$bilinear$ch$2$cells_q$3 cells_q$3(
        .d(cells_q$3$d),
        .q(cells_q$3$q),
        .clock(cells_q$3$clock)
    );
    
    // Update code
    always @(*) begin
        cells_q$0$clock = clock;
        cells_q$1$clock = clock;
        cells_q$2$clock = clock;
        cells_q$3$clock = clock;
        top$clock = clock;
        bottom$clock = clock;
        vertical$clock = clock;
        cells_q$0$d = c00;
        cells_q$1$d = c10;
        cells_q$2$d = c01;
        cells_q$3$d = c11;
        top$a = cells_q$0$q;
        top$b = cells_q$1$q;
        top$w = wx;
        bottom$a = cells_q$2$q;
        bottom$b = cells_q$3$q;
        bottom$w = wx;
        vertical$a = top$y;
        vertical$b = bottom$y;
        vertical$w = wy;
        y = vertical$y;
    end
    
endmodule // top$lanes$3$bilinear$ch$2
module top$lanes$3$bilinear$ch$2$bottom(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$lanes$3$bilinear$ch$2$bottom$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$lanes$3$bilinear$ch$2$bottom$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$lanes$3$bilinear$ch$2$bottom$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$lanes$3$bilinear$ch$2$bottom$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$lanes$3$bilinear$ch$2$bottom$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$lanes$3$bilinear$ch$2$bottom$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$lanes$3$bilinear$ch$2$bottom$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$lanes$3$bilinear$ch$2$bottom$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$lanes$3$bilinear$ch$2$bottom$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$lanes$3$bilinear$ch$2$bottom
module top$lanes$3$bilinear$ch$2$bottom$a_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$2$bottom$a_q
module top$lanes$3$bilinear$ch$2$bottom$a_q2(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$2$bottom$a_q2
module top$lanes$3$bilinear$ch$2$bottom$diff_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$2$bottom$diff_q
module top$lanes$3$bilinear$ch$2$bottom$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$lanes$3$bilinear$ch$2$bottom$narrow
module top$lanes$3$bilinear$ch$2$bottom$prod_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$2$bottom$prod_q
module top$lanes$3$bilinear$ch$2$bottom$up_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$2$bottom$up_q
module top$lanes$3$bilinear$ch$2$bottom$up_q2(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$2$bottom$up_q2
module top$lanes$3$bilinear$ch$2$bottom$w_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$2$bottom$w_q
module top$lanes$3$bilinear$ch$2$bottom$y_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$2$bottom$y_q
module top$lanes$3$bilinear$ch$2$cells_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$2$cells_q$0
module top$lanes$3$bilinear$ch$2$cells_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$2$cells_q$1
module top$lanes$3$bilinear$ch$2$cells_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$2$cells_q$2
module top$lanes$3$bilinear$ch$2$cells_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$2$cells_q$3
module top$lanes$3$bilinear$ch$2$top(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$lanes$3$bilinear$ch$2$top$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$lanes$3$bilinear$ch$2$top$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$lanes$3$bilinear$ch$2$top$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$lanes$3$bilinear$ch$2$top$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$lanes$3$bilinear$ch$2$top$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$lanes$3$bilinear$ch$2$top$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$lanes$3$bilinear$ch$2$top$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$lanes$3$bilinear$ch$2$top$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$lanes$3$bilinear$ch$2$top$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$lanes$3$bilinear$ch$2$top
module top$lanes$3$bilinear$ch$2$top$a_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$2$top$a_q
module top$lanes$3$bilinear$ch$2$top$a_q2(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$2$top$a_q2
module top$lanes$3$bilinear$ch$2$top$diff_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$2$top$diff_q
module top$lanes$3$bilinear$ch$2$top$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$lanes$3$bilinear$ch$2$top$narrow
module top$lanes$3$bilinear$ch$2$top$prod_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$2$top$prod_q
module top$lanes$3$bilinear$ch$2$top$up_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$2$top$up_q
module top$lanes$3$bilinear$ch$2$top$up_q2(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$2$top$up_q2
module top$lanes$3$bilinear$ch$2$top$w_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$2$top$w_q
module top$lanes$3$bilinear$ch$2$top$y_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$2$top$y_q
module top$lanes$3$bilinear$ch$2$vertical(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$lanes$3$bilinear$ch$2$vertical$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$lanes$3$bilinear$ch$2$vertical$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$lanes$3$bilinear$ch$2$vertical$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$lanes$3$bilinear$ch$2$vertical$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$lanes$3$bilinear$ch$2$vertical$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$lanes$3$bilinear$ch$2$vertical$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$lanes$3$bilinear$ch$2$vertical$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$lanes$3$bilinear$ch$2$vertical$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$lanes$3$bilinear$ch$2$vertical$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$lanes$3$bilinear$ch$2$vertical
module top$lanes$3$bilinear$ch$2$vertical$a_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$2$vertical$a_q
module top$lanes$3$bilinear$ch$2$vertical$a_q2(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$2$vertical$a_q2
module top$lanes$3$bilinear$ch$2$vertical$diff_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$2$vertical$diff_q
module top$lanes$3$bilinear$ch$2$vertical$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$lanes$3$bilinear$ch$2$vertical$narrow
module top$lanes$3$bilinear$ch$2$vertical$prod_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$2$vertical$prod_q
module top$lanes$3$bilinear$ch$2$vertical$up_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$2$vertical$up_q
module top$lanes$3$bilinear$ch$2$vertical$up_q2(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$2$vertical$up_q2
module top$lanes$3$bilinear$ch$2$vertical$w_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$2$vertical$w_q
module top$lanes$3$bilinear$ch$2$vertical$y_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$2$vertical$y_q
module top$lanes$3$bilinear$ch$3(clock,c00,c10,c01,c11,wx,wy,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] c00;
    input wire  [31:0] c10;
    input wire  [31:0] c01;
    input wire  [31:0] c11;
    input wire  [15:0] wx;
    input wire  [15:0] wy;
    output reg  [31:0] y;
    
    // Stub signals
    reg  top$clock;
    reg  [31:0] top$a;
    reg  [31:0] top$b;
    reg  [15:0] top$w;
    wire  [31:0] top$y;
    reg  bottom$clock;
    reg  [31:0] bottom$a;
    reg  [31:0] bottom$b;
    reg  [15:0] bottom$w;
    wire  [31:0] bottom$y;
    reg  vertical$clock;
    reg  [31:0] vertical$a;
    reg  [31:0] vertical$b;
    reg  [15:0] vertical$w;
    wire  [31:0] vertical$y;
    reg  [31:0] cells_q$0$d;
    wire  [31:0] cells_q$0$q;
    reg  cells_q$0$clock;
    reg  [31:0] cells_q$1$d;
    wire  [31:0] cells_q$1$q;
    reg  cells_q$1$clock;
    reg  [31:0] cells_q$2$d;
    wire  [31:0] cells_q$2$q;
    reg  cells_q$2$clock;
    reg  [31:0] cells_q$3$d;
    wire  [31:0] cells_q$3$q;
    reg  cells_q$3$clock;
    
    // Sub module instances
    top$lanes$3$bilinear$ch$3$top top(
        .clock(top$clock),
        .a(top$a),
        .b(top$b),
        .w(top$w),
        .y(top$y)
    );
    top$lanes$3$bilinear$ch$3$bottom bottom(
        .clock(bottom$clock),
        .a(bottom$a),
        .b(bottom$b),
        .w(bottom$w),
        .y(bottom$y)
    );
    top$lanes$3$bilinear$ch$3$vertical vertical(
        .clock(vertical$clock),
        .a(vertical$a),
        .b(vertical$b),
        .w(vertical$w),
        .y(vertical$y)
    );
    top$lanes$3$bilinear$ch$3$cells_q$0 cells_q$0(
        .d(cells_q$0$d),
        .q(cells_q$0$q),
        .clock(cells_q$0$clock)
    );
    top$lanes$3$bilinear$ch$3$cells_q$1 cells_q$1(
        .d(cells_q$1$d),
        .q(cells_q$1$q),
        .clock(cells_q$1$clock)
    );
    top$lanes$3$bilinear$ch$3$cells_q$2 cells_q$2(
        .d(cells_q$2$d),
        .q(cells_q$2$q),
        .clock(cells_q$2$clock)
    );
    top$lanes$3$bilinear$ch$3$cells_q$3 cells_q$3(
        .d(cells_q$3$d),
        .q(cells_q$3$q),
        .clock(cells_q$3$clock)
    );
    
    // Update code
    always @(*) begin
        cells_q$0$clock = clock;
        cells_q$1$clock = clock;
        cells_q$2$clock = clock;
        cells_q$3$clock = clock;
        top$clock = clock;
        bottom$clock = clock;
        vertical$clock = clock;
        cells_q$0$d = c00;
        cells_q$1$d = c10;
        cells_q$2$d = c01;
        cells_q$3$d = c11;
        top$a = cells_q$0$q;
        top$b = cells_q$1$q;
        top$w = wx;
        bottom$a = cells_q$2$q;
        bottom$b = cells_q$3$q;
        bottom$w = wx;
        vertical$a = top$y;
        vertical$b = bottom$y;
        vertical$w = wy;
        y = vertical$y;
    end
    
endmodule // top$lanes$3$bilinear$ch$3
module top$lanes$3$bilinear$ch$3$bottom(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$lanes$3$bilinear$ch$3$bottom$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$lanes$3$bilinear$ch$3$bottom$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$lanes$3$bilinear$ch$3$bottom$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$lanes$3$bilinear$ch$3$bottom$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$lanes$3$bilinear$ch$3$bottom$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$lanes$3$bilinear$ch$3$bottom$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$lanes$3$bilinear$ch$3$bottom$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$lanes$3$bilinear$ch$3$bottom$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$lanes$3$bilinear$ch$3$bottom$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$lanes$3$bilinear$ch$3$bottom
module top$lanes$3$bilinear$ch$3$bottom$a_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$3$bottom$a_q
module top$lanes$3$bilinear$ch$3$bottom$a_q2(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$3$bottom$a_q2
module top$lanes$3$bilinear$ch$3$bottom$diff_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$3$bottom$diff_q
module top$lanes$3$bilinear$ch$3$bottom$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$lanes$3$bilinear$ch$3$bottom$narrow
module top$lanes$3$bilinear$ch$3$bottom$prod_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$3$bottom$prod_q
module top$lanes$3$bilinear$ch$3$bottom$up_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$3$bottom$up_q
module top$lanes$3$bilinear$ch$3$bottom$up_q2(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$3$bottom$up_q2
module top$lanes$3$bilinear$ch$3$bottom$w_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$3$bottom$w_q
module top$lanes$3$bilinear$ch$3$bottom$y_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$3$bottom$y_q
module top$lanes$3$bilinear$ch$3$cells_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$3$cells_q$0
module top$lanes$3$bilinear$ch$3$cells_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$3$cells_q$1
module top$lanes$3$bilinear$ch$3$cells_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$3$cells_q$2
module top$lanes$3$bilinear$ch$3$cells_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$3$cells_q$3
module top$lanes$3$bilinear$ch$3$top(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$lanes$3$bilinear$ch$3$top$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$lanes$3$bilinear$ch$3$top$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$lanes$3$bilinear$ch$3$top$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$lanes$3$bilinear$ch$3$top$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$lanes$3$bilinear$ch$3$top$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$lanes$3$bilinear$ch$3$top$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$lanes$3$bilinear$ch$3$top$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$lanes$3$bilinear$ch$3$top$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$lanes$3$bilinear$ch$3$top$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$lanes$3$bilinear$ch$3$top
module top$lanes$3$bilinear$ch$3$top$a_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$3$top$a_q
module top$lanes$3$bilinear$ch$3$top$a_q2(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$3$top$a_q2
module top$lanes$3$bilinear$ch$3$top$diff_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$3$top$diff_q
module top$lanes$3$bilinear$ch$3$top$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$lanes$3$bilinear$ch$3$top$narrow
module top$lanes$3$bilinear$ch$3$top$prod_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$3$top$prod_q
module top$lanes$3$bilinear$ch$3$top$up_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$3$top$up_q
module top$lanes$3$bilinear$ch$3$top$up_q2(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$3$top$up_q2
module top$lanes$3$bilinear$ch$3$top$w_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$3$top$w_q
module top$lanes$3$bilinear$ch$3$top$y_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$3$top$y_q
module top$lanes$3$bilinear$ch$3$vertical(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$lanes$3$bilinear$ch$3$vertical$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$lanes$3$bilinear$ch$3$vertical$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$lanes$3$bilinear$ch$3$vertical$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$lanes$3$bilinear$ch$3$vertical$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$lanes$3$bilinear$ch$3$vertical$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$lanes$3$bilinear$ch$3$vertical$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$lanes$3$bilinear$ch$3$vertical$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$lanes$3$bilinear$ch$3$vertical$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$lanes$3$bilinear$ch$3$vertical$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$lanes$3$bilinear$ch$3$vertical
module top$lanes$3$bilinear$ch$3$vertical$a_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$3$vertical$a_q
module top$lanes$3$bilinear$ch$3$vertical$a_q2(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$3$vertical$a_q2
module top$lanes$3$bilinear$ch$3$vertical$diff_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$3$vertical$diff_q
module top$lanes$3$bilinear$ch$3$vertical$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$lanes$3$bilinear$ch$3$vertical$narrow
module top$lanes$3$bilinear$ch$3$vertical$prod_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$3$vertical$prod_q
module top$lanes$3$bilinear$ch$3$vertical$up_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$3$vertical$up_q
module top$lanes$3$bilinear$ch$3$vertical$up_q2(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$3$vertical$up_q2
module top$lanes$3$bilinear$ch$3$vertical$w_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$3$vertical$w_q
module top$lanes$3$bilinear$ch$3$vertical$y_q(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$ch$3$vertical$y_q
module top$lanes$3$bilinear$wx_q$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$3$bilinear$wx_q$0
module top$lanes$3$bilinear$wx_q$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$3$bilinear$wx_q$1
module top$lanes$3$bilinear$wx_q$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$3$bilinear$wx_q$2
module top$lanes$3$bilinear$wx_q$3(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$3$bilinear$wx_q$3
module top$lanes$3$bilinear$wy_last$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$3$bilinear$wy_last$0
module top$lanes$3$bilinear$wy_last$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$3$bilinear$wy_last$1
module top$lanes$3$bilinear$wy_last$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$3$bilinear$wy_last$2
module top$lanes$3$bilinear$wy_last$3(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$3$bilinear$wy_last$3
module top$lanes$3$bilinear$wy_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$wy_q$0
module top$lanes$3$bilinear$wy_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$wy_q$1
module top$lanes$3$bilinear$wy_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$3$bilinear$wy_q$2
