module top$cfb$lanes$0$div_x(num,den,q,overflow);
    
    // Module arguments
    input wire  [63:0] num;
    input wire  [63:0] den;
    output reg  [31:0] q;
    output reg  overflow;
    
    // Constant declarations
    localparam  enabled = 1'b1;
    
    // Local signals
    reg  [63:0] rem;
    reg  [31:0] quo;
    
    // Update code
    reg  [31:0] q_pass;
    reg  overflow_pass;
    always @(*) begin
        rem = num;
        quo = 'h0;
        overflow_pass = num >= (den << 'h11);
        if (rem >= (den << ('h10 - 0))) begin
            rem = rem - (den << ('h10 - 0));
            quo = quo | (32'('h1) << ('h10 - 0));
        end
        if (rem >= (den << ('h10 - 1))) begin
            rem = rem - (den << ('h10 - 1));
            quo = quo | (32'('h1) << ('h10 - 1));
        end
        if (rem >= (den << ('h10 - 2))) begin
            rem = rem - (den << ('h10 - 2));
            quo = quo | (32'('h1) << ('h10 - 2));
        end
        if (rem >= (den << ('h10 - 3))) begin
            rem = rem - (den << ('h10 - 3));
            quo = quo | (32'('h1) << ('h10 - 3));
        end
        if (rem >= (den << ('h10 - 4))) begin
            rem = rem - (den << ('h10 - 4));
            quo = quo | (32'('h1) << ('h10 - 4));
        end
        if (rem >= (den << ('h10 - 5))) begin
            rem = rem - (den << ('h10 - 5));
            quo = quo | (32'('h1) << ('h10 - 5));
        end
        if (rem >= (den << ('h10 - 6))) begin
            rem = rem - (den << ('h10 - 6));
            quo = quo | (32'('h1) << ('h10 - 6));
        end
        if (rem >= (den << ('h10 - 7))) begin
            rem = rem - (den << ('h10 - 7));
            quo = quo | (32'('h1) << ('h10 - 7));
        end
        if (rem >= (den << ('h10 - 8))) begin
            rem = rem - (den << ('h10 - 8));
            quo = quo | (32'('h1) << ('h10 - 8));
        end
        if (rem >= (den << ('h10 - 9))) begin
            rem = rem - (den << ('h10 - 9));
            quo = quo | (32'('h1) << ('h10 - 9));
        end
        if (rem >= (den << ('h10 - 10))) begin
            rem = rem - (den << ('h10 - 10));
            quo = quo | (32'('h1) << ('h10 - 10));
        end
        if (rem >= (den << ('h10 - 11))) begin
            rem = rem - (den << ('h10 - 11));
            quo = quo | (32'('h1) << ('h10 - 11));
        end
        if (rem >= (den << ('h10 - 12))) begin
            rem = rem - (den << ('h10 - 12));
            quo = quo | (32'('h1) << ('h10 - 12));
        end
        if (rem >= (den << ('h10 - 13))) begin
            rem = rem - (den << ('h10 - 13));
            quo = quo | (32'('h1) << ('h10 - 13));
        end
        if (rem >= (den << ('h10 - 14))) begin
            rem = rem - (den << ('h10 - 14));
            quo = quo | (32'('h1) << ('h10 - 14));
        end
        if (rem >= (den << ('h10 - 15))) begin
            rem = rem - (den << ('h10 - 15));
            quo = quo | (32'('h1) << ('h10 - 15));
        end
        if (rem >= (den << ('h10 - 16))) begin
            rem = rem - (den << ('h10 - 16));
            quo = quo | (32'('h1) << ('h10 - 16));
        end
        q_pass = quo;
        if (~enabled) begin
            q_pass = 'h0;
            overflow_pass = 1'b0;
        end
        q = q_pass;
        overflow = overflow_pass;
    end
    
endmodule // top$cfb$lanes$0$div_x
module top$cfb$lanes$0$div_y(num,den,q,overflow);
    
    // Module arguments
    input wire  [63:0] num;
    input wire  [63:0] den;
    output reg  [31:0] q;
    output reg  overflow;
    
    // Constant declarations
    localparam  enabled = 1'b1;
    
    // Local signals
    reg  [63:0] rem;
    reg  [31:0] quo;
    
    // Update code
    reg  [31:0] q_pass;
    reg  overflow_pass;
    always @(*) begin
        rem = num;
        quo = 'h0;
        overflow_pass = num >= (den << 'h11);
        if (rem >= (den << ('h10 - 0))) begin
            rem = rem - (den << ('h10 - 0));
            quo = quo | (32'('h1) << ('h10 - 0));
        end
        if (rem >= (den << ('h10 - 1))) begin
            rem = rem - (den << ('h10 - 1));
            quo = quo | (32'('h1) << ('h10 - 1));
        end
        if (rem >= (den << ('h10 - 2))) begin
            rem = rem - (den << ('h10 - 2));
            quo = quo | (32'('h1) << ('h10 - 2));
        end
        if (rem >= (den << ('h10 - 3))) begin
            rem = rem - (den << ('h10 - 3));
            quo = quo | (32'('h1) << ('h10 - 3));
        end
        if (rem >= (den << ('h10 - 4))) begin
            rem = rem - (den << ('h10 - 4));
            quo = quo | (32'('h1) << ('h10 - 4));
        end
        if (rem >= (den << ('h10 - 5))) begin
            rem = rem - (den << ('h10 - 5));
            quo = quo | (32'('h1) << ('h10 - 5));
        end
        if (rem >= (den << ('h10 - 6))) begin
            rem = rem - (den << ('h10 - 6));
            quo = quo | (32'('h1) << ('h10 - 6));
        end
        if (rem >= (den << ('h10 - 7))) begin
            rem = rem - (den << ('h10 - 7));
            quo = quo | (32'('h1) << ('h10 - 7));
        end
        if (rem >= (den << ('h10 - 8))) begin
            rem = rem - (den << ('h10 - 8));
            quo = quo | (32'('h1) << ('h10 - 8));
        end
        if (rem >= (den << ('h10 - 9))) begin
            rem = rem - (den << ('h10 - 9));
            quo = quo | (32'('h1) << ('h10 - 9));
        end
        if (rem >= (den << ('h10 - 10))) begin
            rem = rem - (den << ('h10 - 10));
            quo = quo | (32'('h1) << ('h10 - 10));
        end
        if (rem >= (den << ('h10 - 11))) begin
            rem = rem - (den << ('h10 - 11));
            quo = quo | (32'('h1) << ('h10 - 11));
        end
        if (rem >= (den << ('h10 - 12))) begin
            rem = rem - (den << ('h10 - 12));
            quo = quo | (32'('h1) << ('h10 - 12));
        end
        if (rem >= (den << ('h10 - 13))) begin
            rem = rem - (den << ('h10 - 13));
            quo = quo | (32'('h1) << ('h10 - 13));
        end
        if (rem >= (den << ('h10 - 14))) begin
            rem = rem - (den << ('h10 - 14));
            quo = quo | (32'('h1) << ('h10 - 14));
        end
        if (rem >= (den << ('h10 - 15))) begin
            rem = rem - (den << ('h10 - 15));
            quo = quo | (32'('h1) << ('h10 - 15));
        end
        if (rem >= (den << ('h10 - 16))) begin
            rem = rem - (den << ('h10 - 16));
            quo = quo | (32'('h1) << ('h10 - 16));
        end
        q_pass = quo;
        if (~enabled) begin
            q_pass = 'h0;
            overflow_pass = 1'b0;
        end
        q = q_pass;
        overflow = overflow_pass;
    end
    
endmodule // top$cfb$lanes$0$div_y
module top$cfb$lanes$1$div_x(num,den,q,overflow);
    
    // Module arguments
    input wire  [63:0] num;
    input wire  [63:0] den;
    output reg  [31:0] q;
    output reg  overflow;
    
    // Constant declarations
    localparam  enabled = 1'b1;
    
    // Local signals
    reg  [63:0] rem;
    reg  [31:0] quo;
    
    // Update code
    reg  [31:0] q_pass;
    reg  overflow_pass;
    always @(*) begin
        rem = num;
        quo = 'h0;
        overflow_pass = num >= (den << 'h11);
        if (rem >= (den << ('h10 - 0))) begin
            rem = rem - (den << ('h10 - 0));
            quo = quo | (32'('h1) << ('h10 - 0));
        end
        if (rem >= (den << ('h10 - 1))) begin
            rem = rem - (den << ('h10 - 1));
            quo = quo | (32'('h1) << ('h10 - 1));
        end
        if (rem >= (den << ('h10 - 2))) begin
            rem = rem - (den << ('h10 - 2));
            quo = quo | (32'('h1) << ('h10 - 2));
        end
        if (rem >= (den << ('h10 - 3))) begin
            rem = rem - (den << ('h10 - 3));
            quo = quo | (32'('h1) << ('h10 - 3));
        end
        if (rem >= (den << ('h10 - 4))) begin
            rem = rem - (den << ('h10 - 4));
            quo = quo | (32'('h1) << ('h10 - 4));
        end
        if (rem >= (den << ('h10 - 5))) begin
            rem = rem - (den << ('h10 - 5));
            quo = quo | (32'('h1) << ('h10 - 5));
        end
        if (rem >= (den << ('h10 - 6))) begin
            rem = rem - (den << ('h10 - 6));
            quo = quo | (32'('h1) << ('h10 - 6));
        end
        if (rem >= (den << ('h10 - 7))) begin
            rem = rem - (den << ('h10 - 7));
            quo = quo | (32'('h1) << ('h10 - 7));
        end
        if (rem >= (den << ('h10 - 8))) begin
            rem = rem - (den << ('h10 - 8));
            quo = quo | (32'('h1) << ('h10 - 8));
        end
        if (rem >= (den << ('h10 - 9))) begin
            rem = rem - (den << ('h10 - 9));
            quo = quo | (32'('h1) << ('h10 - 9));
        end
        if (rem >= (den << ('h10 - 10))) begin
            rem = rem - (den << ('h10 - 10));
            quo = quo | (32'('h1) << ('h10 - 10));
        end
        if (rem >= (den << ('h10 - 11))) begin
            rem = rem - (den << ('h10 - 11));
            quo = quo | (32'('h1) << ('h10 - 11));
        end
        if (rem >= (den << ('h10 - 12))) begin
            rem = rem - (den << ('h10 - 12));
            quo = quo | (32'('h1) << ('h10 - 12));
        end
        if (rem >= (den << ('h10 - 13))) begin
            rem = rem - (den << ('h10 - 13));
            quo = quo | (32'('h1) << ('h10 - 13));
        end
        if (rem >= (den << ('h10 - 14))) begin
            rem = rem - (den << ('h10 - 14));
            quo = quo | (32'('h1) << ('h10 - 14));
        end
        if (rem >= (den << ('h10 - 15))) begin
            rem = rem - (den << ('h10 - 15));
            quo = quo | (32'('h1) << ('h10 - 15));
        end
        if (rem >= (den << ('h10 - 16))) begin
            rem = rem - (den << ('h10 - 16));
            quo = quo | (32'('h1) << ('h10 - 16));
        end
        q_pass = quo;
        if (~enabled) begin
            q_pass = 'h0;
            overflow_pass = 1'b0;
        end
        q = q_pass;
        overflow = overflow_pass;
    end
    
endmodule // top$cfb$lanes$1$div_x
module top$cfb$lanes$1$div_y(num,den,q,overflow);
    
    // Module arguments
    input wire  [63:0] num;
    input wire  [63:0] den;
    output reg  [31:0] q;
    output reg  overflow;
    
    // Constant declarations
    localparam  enabled = 1'b1;
    
    // Local signals
    reg  [63:0] rem;
    reg  [31:0] quo;
    
    // Update code
    reg  [31:0] q_pass;
    reg  overflow_pass;
    always @(*) begin
        rem = num;
        quo = 'h0;
        overflow_pass = num >= (den << 'h11);
        if (rem >= (den << ('h10 - 0))) begin
            rem = rem - (den << ('h10 - 0));
            quo = quo | (32'('h1) << ('h10 - 0));
        end
        if (rem >= (den << ('h10 - 1))) begin
            rem = rem - (den << ('h10 - 1));
            quo = quo | (32'('h1) << ('h10 - 1));
        end
        if (rem >= (den << ('h10 - 2))) begin
            rem = rem - (den << ('h10 - 2));
            quo = quo | (32'('h1) << ('h10 - 2));
        end
        if (rem >= (den << ('h10 - 3))) begin
            rem = rem - (den << ('h10 - 3));
            quo = quo | (32'('h1) << ('h10 - 3));
        end
        if (rem >= (den << ('h10 - 4))) begin
            rem = rem - (den << ('h10 - 4));
            quo = quo | (32'('h1) << ('h10 - 4));
        end
        if (rem >= (den << ('h10 - 5))) begin
            rem = rem - (den << ('h10 - 5));
            quo = quo | (32'('h1) << ('h10 - 5));
        end
        if (rem >= (den << ('h10 - 6))) begin
            rem = rem - (den << ('h10 - 6));
            quo = quo | (32'('h1) << ('h10 - 6));
        end
        if (rem >= (den << ('h10 - 7))) begin
            rem = rem - (den << ('h10 - 7));
            quo = quo | (32'('h1) << ('h10 - 7));
        end
        if (rem >= (den << ('h10 - 8))) begin
            rem = rem - (den << ('h10 - 8));
            quo = quo | (32'('h1) << ('h10 - 8));
        end
        if (rem >= (den << ('h10 - 9))) begin
            rem = rem - (den << ('h10 - 9));
            quo = quo | (32'('h1) << ('h10 - 9));
        end
        if (rem >= (den << ('h10 - 10))) begin
            rem = rem - (den << ('h10 - 10));
            quo = quo | (32'('h1) << ('h10 - 10));
        end
        if (rem >= (den << ('h10 - 11))) begin
            rem = rem - (den << ('h10 - 11));
            quo = quo | (32'('h1) << ('h10 - 11));
        end
        if (rem >= (den << ('h10 - 12))) begin
            rem = rem - (den << ('h10 - 12));
            quo = quo | (32'('h1) << ('h10 - 12));
        end
        if (rem >= (den << ('h10 - 13))) begin
            rem = rem - (den << ('h10 - 13));
            quo = quo | (32'('h1) << ('h10 - 13));
        end
        if (rem >= (den << ('h10 - 14))) begin
            rem = rem - (den << ('h10 - 14));
            quo = quo | (32'('h1) << ('h10 - 14));
        end
        if (rem >= (den << ('h10 - 15))) begin
            rem = rem - (den << ('h10 - 15));
            quo = quo | (32'('h1) << ('h10 - 15));
        end
        if (rem >= (den << ('h10 - 16))) begin
            rem = rem - (den << ('h10 - 16));
            quo = quo | (32'('h1) << ('h10 - 16));
        end
        q_pass = quo;
        if (~enabled) begin
            q_pass = 'h0;
            overflow_pass = 1'b0;
        end
        q = q_pass;
        overflow = overflow_pass;
    end
    
endmodule // top$cfb$lanes$1$div_y
